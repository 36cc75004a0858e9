#pragma once
// Cholesky factorisation of a symmetric positive definite band matrix, in double: the exact
// solve of the coarsest multigrid level (a 9-point operator on at most 64 x 64 points, in
// row-major order a band of width + 1 on each side of the diagonal).

#include <cstddef>
#include <vector>

namespace vicc_glyphs::multigrid_detail {

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
  /// slightly shifted, still positive definite matrix).
  void factorise();
  static constexpr double kPivotFloor = 1e-12;
  /// Solves A x = b in place (x holds b on entry), n values.
  void solve(double* x) const;
  int size() const { return n_; }

 private:
  double factorEntry(int row, int column) const {
    return factor_[static_cast<std::size_t>(row) * (bandwidth_ + 1) + (column - row + bandwidth_)];
  }

  int n_ = 0;
  int bandwidth_ = 0;
  std::vector<double> factor_;
  std::vector<double> original_diagonal_;
};

}  // namespace vicc_glyphs::multigrid_detail
