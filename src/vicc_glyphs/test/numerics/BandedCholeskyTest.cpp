// The banded Cholesky against Eigen's dense factorisation, and what it does with a singular or
// nearly singular matrix: raise the pivot (the renderer's coarsest level) and say so (the
// B-spline fits, for which that is an error).

#include "vicc_glyphs/numerics/banded_cholesky.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

namespace vicc_glyphs::numerics {
namespace {

TEST(BandedCholeskyTest, SolvesLikeADenseFactorisation) {
  // A 9-point operator on 7 x 5 points in row-major order (band 8) plus a diagonal shift.
  const int w = 7, h = 5, n = w * h;
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> coupling(0.1, 1.0);
  for (int k = 0; k < n; ++k) {
    for (const auto& [dx, dy] : {std::pair{1, 0}, {-1, 1}, {0, 1}, {1, 1}}) {
      const int x = k % w + dx, y = k / w + dy;
      if (x < 0 || x >= w || y >= h) continue;
      const double a = coupling(random);
      dense(k, y * w + x) = dense(y * w + x, k) = -a;
      dense(k, k) += a;
      dense(y * w + x, y * w + x) += a;
    }
    dense(k, k) += 0.05;
  }
  BandedCholesky cholesky;
  cholesky.reset(n, w + 1);
  for (int i = 0; i < n; ++i) {
    for (int j = std::max(0, i - w - 1); j <= i; ++j) cholesky.lower(i, j) = dense(i, j);
  }
  cholesky.factorise();
  EXPECT_EQ(cholesky.raisedPivots(), 0);
  const Eigen::LLT<Eigen::MatrixXd> llt = dense.llt();
  const Eigen::MatrixXd factor = llt.matrixL();
  EXPECT_NEAR(cholesky.smallestPivot(), factor.diagonal().cwiseAbs2().minCoeff(), 1e-12);
  Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  std::vector<double> x(b.data(), b.data() + n);
  cholesky.solve(x.data());
  const Eigen::VectorXd expected = llt.solve(b);
  for (int k = 0; k < n; ++k) EXPECT_NEAR(x[k], expected[k], 1e-10) << k;
}

TEST(BandedCholeskyTest, RaisesAndCountsPivotsOfASingularMatrix) {
  // Round-off can make a nearly singular coarse operator singular: the pivot is raised, the
  // solve stays finite and solves the consistent system approximately.
  BandedCholesky cholesky;
  cholesky.reset(2, 1);
  cholesky.lower(0, 0) = 1.0;
  cholesky.lower(1, 0) = 1.0;
  cholesky.lower(1, 1) = 1.0;
  cholesky.factorise();
  EXPECT_EQ(cholesky.raisedPivots(), 1);
  EXPECT_NEAR(cholesky.smallestPivot(), BandedCholesky::kPivotFloor, 1e-15);
  double consistent[2] = {1.0, 1.0};
  cholesky.solve(consistent);
  EXPECT_TRUE(std::isfinite(consistent[0]) && std::isfinite(consistent[1]));
  EXPECT_NEAR(consistent[0] + consistent[1], 1.0, 1e-6);
  // A factorisation starts counting afresh; NaN entries count as raised pivots.
  cholesky.reset(3, 1);
  for (int i = 0; i < 3; ++i) cholesky.lower(i, i) = 2.0;
  cholesky.lower(1, 0) = cholesky.lower(2, 1) = 1.0;
  cholesky.factorise();
  EXPECT_EQ(cholesky.raisedPivots(), 0);
  EXPECT_NEAR(cholesky.smallestPivot(), 4.0 / 3.0, 1e-12);  // 2 - 1/2, then 2 - 1/1.5
  cholesky.reset(2, 1);
  cholesky.lower(0, 0) = 1.0;
  cholesky.lower(1, 1) = std::nan("");
  cholesky.factorise();
  EXPECT_EQ(cholesky.raisedPivots(), 1);
}

TEST(BandedCholeskyTest, SolvesSeveralRightHandSidesExactlyAsOneByOne) {
  // The fits solve x and y together and the renderer its three channels: each column must get
  // the same bits as its own solve (the glyphs' outputs are compared byte for byte).
  const int n = 40, band = 6;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  BandedCholesky cholesky;
  cholesky.reset(n, band);
  for (int i = 0; i < n; ++i) {
    for (int j = std::max(0, i - band); j < i; ++j) cholesky.lower(i, j) = entry(random);
    cholesky.lower(i, i) = 2.0 * band + 1.0;  // diagonally dominant
  }
  cholesky.factorise();
  ASSERT_EQ(cholesky.raisedPivots(), 0);
  std::vector<std::vector<double>> columns(3, std::vector<double>(n));
  for (auto& column : columns) {
    for (double& value : column) value = entry(random);
  }
  std::vector<std::vector<double>> alone = columns, pair = columns, triple = columns;
  for (auto& column : alone) cholesky.solve(column.data());
  cholesky.solve(pair[0].data(), pair[1].data());
  cholesky.solve(triple[0].data(), triple[1].data(), triple[2].data());
  for (int c = 0; c < 3; ++c) {
    EXPECT_NE(alone[c], columns[c]);
    EXPECT_EQ(triple[c], alone[c]) << "column " << c;  // bitwise: vector<double> ==
    if (c < 2) {
      EXPECT_EQ(pair[c], alone[c]) << "column " << c;
    }
  }
}

}  // namespace
}  // namespace vicc_glyphs::numerics
