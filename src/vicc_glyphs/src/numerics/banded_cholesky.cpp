#include "vicc_glyphs/numerics/banded_cholesky.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vicc_glyphs::numerics {

void BandedCholesky::reset(int n, int bandwidth) {
  n_ = n;
  bandwidth_ = std::max(0, std::min(bandwidth, n - 1));
  factor_.assign(static_cast<size_t>(n) * (bandwidth_ + 1), 0.0);
}

void BandedCholesky::factorise() {
  original_diagonal_.resize(n_);
  raised_pivots_ = 0;
  smallest_pivot_ = n_ > 0 ? std::numeric_limits<double>::infinity() : 0.0;
  for (int i = 0; i < n_; ++i) original_diagonal_[i] = factorEntry(i, i);
  for (int i = 0; i < n_; ++i) {
    const int first = std::max(0, i - bandwidth_);
    for (int j = first; j <= i; ++j) {
      double sum = factorEntry(i, j);
      for (int k = std::max(first, j - bandwidth_); k < j; ++k) {
        sum -= factorEntry(i, k) * factorEntry(j, k);
      }
      if (j < i) {
        lower(i, j) = sum / factorEntry(j, j);
      } else {
        // The renderer's coarse operators are positive definite by construction; float
        // round-off in a nearly singular one (a region pinned by a single pixel) can still
        // leave a pivot at or below 0. A small positive pivot keeps the coarse solve symmetric
        // positive definite (the preconditioner stays valid; CG corrects the approximation).
        const double diagonal = std::abs(original_diagonal_[i]);
        const double floor = kPivotFloor * (diagonal > 0.0 ? diagonal : 1.0);
        // Not `sum <= floor`: a NaN sum counts as raised too.
        if (!(sum > floor)) ++raised_pivots_;
        const double pivot = std::max(sum, floor);
        smallest_pivot_ = std::min(smallest_pivot_, pivot);
        lower(i, i) = std::sqrt(pivot);
      }
    }
  }
}

template <int kCount>
void BandedCholesky::solveColumns(double* const* columns) const {
  double sum[kCount];
  for (int i = 0; i < n_; ++i) {  // L y = b
    for (int c = 0; c < kCount; ++c) sum[c] = columns[c][i];
    for (int k = std::max(0, i - bandwidth_); k < i; ++k) {
      const double entry = factorEntry(i, k);
      for (int c = 0; c < kCount; ++c) sum[c] -= entry * columns[c][k];
    }
    const double pivot = factorEntry(i, i);
    for (int c = 0; c < kCount; ++c) columns[c][i] = sum[c] / pivot;
  }
  for (int i = n_ - 1; i >= 0; --i) {  // L^T x = y
    for (int c = 0; c < kCount; ++c) sum[c] = columns[c][i];
    for (int k = i + 1; k <= std::min(n_ - 1, i + bandwidth_); ++k) {
      const double entry = factorEntry(k, i);
      for (int c = 0; c < kCount; ++c) sum[c] -= entry * columns[c][k];
    }
    const double pivot = factorEntry(i, i);
    for (int c = 0; c < kCount; ++c) columns[c][i] = sum[c] / pivot;
  }
}

void BandedCholesky::solve(double* x) const {
  double* const columns[] = {x};
  solveColumns<1>(columns);
}

void BandedCholesky::solve(double* x, double* y) const {
  double* const columns[] = {x, y};
  solveColumns<2>(columns);
}

void BandedCholesky::solve(double* x, double* y, double* z) const {
  double* const columns[] = {x, y, z};
  solveColumns<3>(columns);
}

}  // namespace vicc_glyphs::numerics
