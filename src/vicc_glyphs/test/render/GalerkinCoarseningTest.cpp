// The coarse operators of the multigrid against dense products and the prolongation's respect
// for cut links (the coarsest level's banded Cholesky: test/numerics/BandedCholeskyTest.cpp).

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "direct_reference_solve.hpp"
#include "multigrid_levels.hpp"

namespace vicc_glyphs::multigrid_detail {
namespace {

using Sparse = Eigen::SparseMatrix<double>;

// Random cut links and Dirichlet pixels in the columns left of `irregular_width`, none right of
// it: coarsen() works out the left part point by point and takes its regular stencil on the
// right, and both must equal the dense product.
GridProblem randomProblem(int width, int height, int irregular_width, unsigned seed) {
  GridProblem problem = openGridProblem(width, height, 1);
  std::mt19937 random(seed);
  std::bernoulli_distribution cut(0.25), pin(0.12);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < irregular_width; ++x) {
      const int p = y * width + x;
      if (cut(random)) problem.couples_right[p] = 0;
      if (cut(random)) problem.couples_down[p] = 0;
      problem.fixed[p] = pin(random);
    }
  }
  return problem;
}

// A level's matrix over all its points (index y * width + x; zero rows and columns at the
// points that are not unknowns).
template <class Level>
Sparse matrixOf(const Level& level) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int y = 0; y < level.height; ++y) {
    for (int x = 0; x < level.width; ++x) {
      const Stencil a = level.row(level.index(x, y));
      for (int k = 0; k < 9; ++k) {
        const int qx = x + k % 3 - 1, qy = y + k / 3 - 1;
        if (a[k] == 0.0f) continue;
        EXPECT_TRUE(qx >= 0 && qy >= 0 && qx < level.width && qy < level.height);
        entries.emplace_back(y * level.width + x, qy * level.width + qx, a[k]);
      }
    }
  }
  Sparse matrix(level.width * level.height, level.width * level.height);
  matrix.setFromTriplets(entries.begin(), entries.end());
  return matrix;
}

// P as a matrix (fine points x coarse points), from the per-cell weights as the solver uses
// them: fine point (2i, 2j) takes coarse point (i, j)'s value when it is an unknown.
template <class Level>
Sparse prolongationOf(const Level& fine, const Transfer& transfer, const CoarseLevel& coarse) {
  std::vector<Eigen::Triplet<double>> entries;
  const auto add = [&](int fx, int fy, int cx, int cy, float weight) {
    // The random problems have free pixels without links (the assembler makes those Dirichlet
    // pixels): their weights are 0, not NaN (a NaN slips through the comparisons below).
    EXPECT_TRUE(std::isfinite(weight) && weight >= 0.0f) << weight << " at " << fx << ", " << fy;
    if (weight == 0.0f) return;
    EXPECT_TRUE(fx < fine.width && fy < fine.height && cx < coarse.width && cy < coarse.height);
    entries.emplace_back(fy * fine.width + fx, cy * coarse.width + cx, weight);
  };
  for (int j = 0; j < coarse.height; ++j) {
    for (int i = 0; i < coarse.width; ++i) {
      const CellWeights& w = transfer[coarse.index(i, j)];
      if (fine.isFree(fine.index(2 * i, 2 * j))) add(2 * i, 2 * j, i, j, 1.0f);
      add(2 * i + 1, 2 * j, i, j, w.x_west);
      add(2 * i + 1, 2 * j, i + 1, j, w.x_east);
      add(2 * i, 2 * j + 1, i, j, w.y_north);
      add(2 * i, 2 * j + 1, i, j + 1, w.y_south);
      add(2 * i + 1, 2 * j + 1, i, j, w.nw);
      add(2 * i + 1, 2 * j + 1, i + 1, j, w.ne);
      add(2 * i + 1, 2 * j + 1, i, j + 1, w.sw);
      add(2 * i + 1, 2 * j + 1, i + 1, j + 1, w.se);
    }
  }
  Sparse matrix(fine.width * fine.height, coarse.width * coarse.height);
  matrix.setFromTriplets(entries.begin(), entries.end());
  return matrix;
}

void expectMatricesNear(const Sparse& actual, const Sparse& expected, double tolerance) {
  const Eigen::MatrixXd a(actual), e(expected);
  ASSERT_EQ(a.rows(), e.rows());
  ASSERT_EQ(a.cols(), e.cols());
  Eigen::Index row = 0, col = 0;
  const double largest = (a - e).cwiseAbs().maxCoeff(&row, &col);
  EXPECT_LE(largest, tolerance) << "at (" << row << ", " << col << "): " << a(row, col)
                                << " instead of " << e(row, col);
}

struct Hierarchy {
  FineLevel fine;
  CoarseLevel level1, level2;
  Transfer transfer0, transfer1;
};

void coarsenTwice(const GridProblem& problem, Hierarchy& h) {
  std::vector<std::uint8_t> scratch;
  makeFineLevel(problem, h.fine);
  resizeCoarseLevel((problem.width + 1) / 2, (problem.height + 1) / 2, h.level1);
  coarsen(h.fine, h.transfer0, h.level1, scratch);
  resizeCoarseLevel((h.level1.width + 1) / 2, (h.level1.height + 1) / 2, h.level2);
  coarsen(h.level1, h.transfer1, h.level2, scratch);
}

TEST(GalerkinCoarseningTest, CoarseOperatorsAreTheDenseProductsRAP) {
  for (const auto& [width, height] : {std::pair{61, 45}, std::pair{64, 40}}) {
    const GridProblem problem = randomProblem(width, height, 24, 7u + width);
    Hierarchy h;
    coarsenTwice(problem, h);
    const Sparse a0 = matrixOf(h.fine);
    const Sparse p0 = prolongationOf(h.fine, h.transfer0, h.level1);
    const Sparse galerkin1 = Sparse(p0.transpose()) * a0 * p0;
    SCOPED_TRACE(std::to_string(width) + " x " + std::to_string(height));
    expectMatricesNear(matrixOf(h.level1), galerkin1, 1e-5);
    const Sparse p1 = prolongationOf(h.level1, h.transfer1, h.level2);
    const Sparse galerkin2 = Sparse(p1.transpose()) * matrixOf(h.level1) * p1;
    expectMatricesNear(matrixOf(h.level2), galerkin2, 1e-5);
    // Level 1 has a regular part away from the random one (its stencil: bilinear R A P of the
    // 5-point Laplacian).
    const Stencil interior = h.level1.row(h.level1.index(h.level1.width - 8, h.level1.height / 2));
    const Stencil expected{-0.25f, -0.5f, -0.25f, -0.5f, 3.0f, -0.5f, -0.25f, -0.5f, -0.25f};
    for (int k = 0; k < 9; ++k) EXPECT_FLOAT_EQ(interior[k], expected[k]) << k;
  }
}

TEST(GalerkinCoarseningTest, ProlongationDoesNotCrossCutLinksAndKeepsConstants) {
  // Barriers between fine columns 6 | 7 (x-edge 7 of coarse 3 | 4) and 13 | 14 (after the
  // coarse point at 12, before the x-edge 13); Dirichlet pixels in columns 0 and 19.
  GridProblem problem = openGridProblem(20, 12, 1);
  for (int y = 0; y < problem.height; ++y) {
    problem.couples_right[y * 20 + 6] = 0;
    problem.couples_right[y * 20 + 13] = 0;
    problem.fixed[y * 20] = problem.fixed[y * 20 + 19] = 1;
  }
  Hierarchy h;
  coarsenTwice(problem, h);
  const Eigen::MatrixXd p(prolongationOf(h.fine, h.transfer0, h.level1));
  const auto side = [](int fine_x) { return fine_x <= 6 ? 0 : fine_x <= 13 ? 1 : 2; };
  for (int f = 0; f < p.rows(); ++f) {
    const int fx = f % 20, fy = f / 20;
    const bool coarse_point = fx % 2 == 0 && fy % 2 == 0;
    for (int c = 0; c < p.cols(); ++c) {
      if (p(f, c) == 0.0) continue;
      EXPECT_EQ(side(fx), side(2 * (c % h.level1.width))) << "fine " << f << " coarse " << c;
    }
    if (problem.fixed[f]) {
      EXPECT_EQ(p.row(f).sum(), 0.0) << f;
    } else if ((fx >= 2 && fx <= 16) || coarse_point) {  // constants interpolate
      EXPECT_NEAR(p.row(f).sum(), 1.0, 1e-6) << f;
    } else if (fx == 1 || fx == 18) {  // the correction falls towards the Dirichlet pixels
      EXPECT_LT(p.row(f).sum(), 1.0 - 1e-3) << f;
    } else {
      EXPECT_LE(p.row(f).sum(), 1.0 + 1e-6) << f;
    }
  }
}

}  // namespace
}  // namespace vicc_glyphs::multigrid_detail
