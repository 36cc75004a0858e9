#pragma once
// B-spline interpolation and least-squares approximation (thesis 2.5.3, Eqs. 2.43 and 2.47).

#include <Eigen/SparseCore>
#include <vector>

#include "vicc_glyphs/bspline/bspline_curve.hpp"
#include "vicc_glyphs/numerics/banded_cholesky.hpp"

namespace vicc_glyphs {
namespace bspline {

/// Collocation matrix N of Eq. 2.43: entry (i, j) is N_j (or its derivative of `order`) at
/// parameters[i], for the basis given by the degree and knots of `basis` (its de Boor points are
/// ignored). Throws std::invalid_argument for a parameter outside the domain or not finite.
Eigen::SparseMatrix<double> collocationMatrix(const BSplineCurve& basis,
                                              const std::vector<double>& parameters, int order = 0);

/// Chord-length parameters for `points` (the discrete form of the arc-length choice, thesis
/// 2.5.3) spread over [begin, end]; equal spacing where all points coincide.
std::vector<double> chordLengthParameters(const std::vector<Point2>& points, double begin,
                                          double end);

/// Least-squares fit (Eq. 2.47): the de Boor points D minimising sum |s(u_i) - p_i|^2 for the
/// given degree and knot vector, solved by sparse QR (same minimiser as N^T N D = N^T P, better
/// conditioned). Interpolates when there are as many points as de Boor points. Throws
/// std::invalid_argument for mismatched sizes, non-finite data, parameters outside the domain
/// or when the points do not determine all de Boor points (a knot span without enough
/// parameters, Schoenberg-Whitney).
BSplineCurve leastSquaresFit(int degree, std::vector<double> knots,
                             const std::vector<Point2>& points,
                             const std::vector<double>& parameters);

/// Least squares on a cubic basis at fixed parameters, for many sets of points: the normal
/// equations N^T N D = N^T P (the minimiser leastSquaresFit finds by QR). N^T N is banded (each
/// parameter touches four neighbouring basis functions, 3 entries left of the diagonal), so it
/// is summed from the basis rows directly into a band and factorised once (banded Cholesky, no
/// fill-in); every solve costs one back substitution per coordinate. For data that determine
/// the curve well (many parameters per span); QR is the better conditioned choice for
/// interpolation-like fits.
class CubicLeastSquares {
 public:
  /// `basis`: a cubic (its de Boor points are ignored); `parameters` must not decrease and lie in
  /// its domain. Throws std::invalid_argument for another degree, a bad parameter or when the
  /// parameters do not determine every de Boor point (N^T N not positive definite: a pivot at
  /// or below BandedCholesky::kPivotFloor times its diagonal entry).
  CubicLeastSquares(const BSplineCurve& basis, const std::vector<double>& parameters);

  int parameterCount() const { return static_cast<int>(rows_.size()); }
  /// The de Boor points for one target point per parameter (row i for parameters[i]).
  Eigen::MatrixX2d solve(const Eigen::MatrixX2d& targets) const;
  /// solve() as a list of de Boor points.
  std::vector<Point2> solvePoints(const Eigen::MatrixX2d& targets) const;

 private:
  int control_count_ = 0;
  std::vector<CubicBasisRow> rows_;
  numerics::BandedCholesky factor_;
};

}  // namespace bspline
}  // namespace vicc_glyphs
