#pragma once
// Cholesky factorisation of a symmetric positive definite band matrix, in double: the exact
// solve of the renderer's coarsest multigrid level (a 9-point operator on at most 64 x 64 points,
// in row-major order a band of width + 1 on each side of the diagonal) and the B-spline fits'
// normal equations (a cubic's N^T N has 3 entries left of the diagonal). A general sparse
// factorisation (Eigen's SimplicialLLT) spent more in its bookkeeping than in the arithmetic
// on such bands.

#include <cstddef>
#include <vector>

namespace vicc_glyphs::numerics {

class BandedCholesky {
 public:
  /// Starts a matrix of size n x n with `bandwidth` entries left of the diagonal, all zero.
  void reset(int n, int bandwidth);
  /// Entry (row, column) for column <= row, row - column <= bandwidth (the lower band).
  double& lower(int row, int column) {
    return factor_[static_cast<std::size_t>(row) * (bandwidth_ + 1) + (column - row + bandwidth_)];
  }
  /// Factorises the lower band in place. A pivot that round-off leaves at or below
  /// kPivotFloor times its diagonal entry is raised to that (the factor then belongs to a
  /// slightly shifted, still positive definite matrix); raisedPivots() counts them, so that a
  /// caller for whom a singular matrix is an error can say so.
  void factorise();
  static constexpr double kPivotFloor = 1e-12;
  /// Pivots the last factorise() raised to the floor.
  int raisedPivots() const { return raised_pivots_; }
  /// The smallest squared diagonal entry of the factor (the D of L D L^T) after factorise().
  double smallestPivot() const { return smallest_pivot_; }
  /// Solves A x = b in place (x holds b on entry), n values.
  void solve(double* x) const;
  /// Solves for two (three) right-hand sides in distinct arrays at once, each with exactly the
  /// operations of solve(): the substitutions' chains of dependent divisions then overlap
  /// instead of running one after the other (the fits' x and y, the renderer's colour channels).
  void solve(double* x, double* y) const;
  void solve(double* x, double* y, double* z) const;
  int size() const { return n_; }
  int bandwidth() const { return bandwidth_; }

 private:
  double factorEntry(int row, int column) const {
    return factor_[static_cast<std::size_t>(row) * (bandwidth_ + 1) + (column - row + bandwidth_)];
  }

  template <int kCount>
  void solveColumns(double* const* columns) const;

  int n_ = 0;
  int bandwidth_ = 0;
  int raised_pivots_ = 0;
  double smallest_pivot_ = 0.0;
  std::vector<double> factor_;
  std::vector<double> original_diagonal_;
};

}  // namespace vicc_glyphs::numerics
