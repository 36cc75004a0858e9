// The deflation space of the finest level's CG (pieces split at a hole in a wall, E = Z^T A Z
// against the dense product) and what it buys: a channel behind a one-pixel gap converges in
// fewer iterations, to the direct solve.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "direct_reference_solve.hpp"
#include "multigrid_deflation.hpp"
#include "sample_images.hpp"
#include "vicc_glyphs/render/multigrid.hpp"
#include "vicc_glyphs/render/renderer.hpp"

namespace vicc_glyphs {
namespace {

using multigrid_detail::DeflationSpace;
using multigrid_detail::FineLevel;

// 24 x 16 grid, Dirichlet column x = 0; a closed box of cut links around x 12..21, y 3..12
// except one link into it at (11, 7) -> (12, 7): the pocket behind a one-pixel neck.
GridProblem pocketProblem() {
  GridProblem problem = openGridProblem(24, 16, 1);
  const auto at = [&](int x, int y) { return static_cast<size_t>(y * problem.width + x); };
  for (int y = 0; y < problem.height; ++y) {
    problem.fixed[at(0, y)] = 1;
    problem.values[at(0, y)] = 1.0f;
    if (y >= 3 && y <= 12) {
      if (y != 7) problem.couples_right[at(11, y)] = 0;
      problem.couples_right[at(21, y)] = 0;
    }
  }
  for (int x = 12; x <= 21; ++x) {
    problem.couples_down[at(x, 2)] = 0;
    problem.couples_down[at(x, 12)] = 0;
  }
  return problem;
}

TEST(DeflationSpaceTest, APocketBehindAOnePixelNeckIsAPieceOfItsOwn) {
  FineLevel fine;
  multigrid_detail::makeFineLevel(pocketProblem(), fine);
  DeflationSpace space;
  space.build(fine);
  const std::uint32_t* labels = space.labels();
  const std::uint32_t inside = labels[fine.index(16, 8)];
  std::set<std::uint32_t> box, rest;
  for (int y = 0; y < fine.height; ++y) {
    for (int x = 1; x < fine.width; ++x) {
      const bool in_box = x >= 12 && x <= 21 && y >= 3 && y <= 12;
      (in_box ? box : rest).insert(labels[fine.index(x, y)]);
      // The box's inner pixels (not next to its walls) are one piece.
      if (x > 12 && x < 21 && y > 3 && y < 12) {
        EXPECT_EQ(labels[fine.index(x, y)], inside);
      }
    }
  }
  // No piece on both sides of the hole: the hole in the wall is cut (the pixels along the
  // walls join the inner piece or, at the corners, make pieces of their own).
  for (const std::uint32_t label : box) EXPECT_EQ(rest.count(label), 0u) << label;
  // The Dirichlet column and the ghost border read coefficient count() (0).
  EXPECT_EQ(labels[fine.index(0, 5)], static_cast<std::uint32_t>(space.count()));
  EXPECT_EQ(labels[0], static_cast<std::uint32_t>(space.count()));
}

// Singleton pixels are pieces of their own; the rest are split as without them.
TEST(DeflationSpaceTest, SingletonPixelsArePiecesOfTheirOwn) {
  FineLevel fine;
  multigrid_detail::makeFineLevel(pocketProblem(), fine);
  std::vector<int> singletons;
  for (int y = 6; y <= 8; ++y) {
    for (int x = 15; x <= 17; ++x) singletons.push_back(fine.index(x, y));  // inside the box
  }
  singletons.push_back(fine.index(11, 7));  // in front of the hole
  DeflationSpace space;
  space.build(fine, singletons);
  const std::uint32_t* labels = space.labels();
  std::set<std::uint32_t> singleton_labels;
  for (const int p : singletons) singleton_labels.insert(labels[p]);
  EXPECT_EQ(singleton_labels.size(), singletons.size());
  const std::set<int> listed(singletons.begin(), singletons.end());
  for (int y = 0; y < fine.height; ++y) {
    for (int x = 1; x < fine.width; ++x) {
      const int p = fine.index(x, y);
      if (!listed.count(p)) {
        EXPECT_EQ(singleton_labels.count(labels[p]), 0u) << x << ", " << y;
      }
    }
  }
  // The box's other inner pixels are still one piece, the ring around the singletons included.
  const std::uint32_t inside = labels[fine.index(13, 4)];
  EXPECT_EQ(labels[fine.index(20, 11)], inside);
  EXPECT_EQ(labels[fine.index(14, 7)], inside);
  EXPECT_EQ(labels[fine.index(18, 7)], inside);
}

// E = Z^T A Z, and E^-1 applied through solve(), against dense products over all free pixels,
// without and with singleton pieces (which make E the grid's rows there).
class GalerkinProductTest : public ::testing::TestWithParam<bool> {};

TEST_P(GalerkinProductTest, CoarseMatrixIsTheGalerkinProductOfTheIndicators) {
  GridProblem problem = pocketProblem();
  problem.fixed[5 * problem.width + 17] = 1;  // a Dirichlet pixel inside the pocket as well
  FineLevel fine;
  multigrid_detail::makeFineLevel(problem, fine);
  std::vector<int> singletons;
  if (GetParam()) {
    for (int y = 4; y <= 6; ++y) {
      for (int x = 16; x <= 18; ++x) {
        if (fine.isFree(fine.index(x, y))) singletons.push_back(fine.index(x, y));
      }
    }
  }
  DeflationSpace space;
  space.build(fine, singletons);
  const int k = space.count();
  ASSERT_GE(k, 2);
  const int n = static_cast<int>(fine.size);
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n), z = Eigen::MatrixXd::Zero(n, k);
  std::set<int> boundary(space.boundary().begin(), space.boundary().end());
  for (int y = 0; y < fine.height; ++y) {
    for (int x = 0; x < fine.width; ++x) {
      const int p = fine.index(x, y);
      if (!fine.isFree(p)) continue;
      z(p, space.labels()[p]) = 1.0;
      const multigrid_detail::Stencil row = fine.row(p);
      a(p, p) = row[multigrid_detail::kC];
      const int s = fine.stride;
      for (const auto& [entry, q] : {std::pair{multigrid_detail::kW, p - 1},
                                     {multigrid_detail::kE, p + 1},
                                     {multigrid_detail::kN, p - s},
                                     {multigrid_detail::kS, p + s}}) {
        a(p, q) = row[entry];
      }
    }
  }
  const Eigen::MatrixXd e = z.transpose() * a * z;
  const Eigen::MatrixXd az = a * z;
  for (int p = 0; p < n; ++p) {
    // A Z is 0 away from the boundary pixels.
    if (!boundary.count(p)) {
      EXPECT_LT(az.row(p).cwiseAbs().maxCoeff(), 1e-12) << p;
    }
  }
  Eigen::MatrixXd g = Eigen::MatrixXd::Identity(k, k);
  space.solve(g);  // E^-1
  EXPECT_LT((e * g - Eigen::MatrixXd::Identity(k, k)).cwiseAbs().maxCoeff(), 1e-9);
}

INSTANTIATE_TEST_SUITE_P(WithoutAndWithSingletons, GalerkinProductTest, ::testing::Bool());

DiffusionCurve barrier(const Point2& from, const Point2& to) {
  DiffusionCurve curve = lineCurve(from, to, Color::Zero(), Color::Zero());
  curve.left_emits = false;
  curve.right_emits = false;
  return curve;
}

// A coloured circle and, beside it, a closed channel of barriers 5 px wide and 110 px long,
// diagonal, that one gap of about a pixel in its wall connects to the rest: the channel has no
// Dirichlet pixel; its values come through the gap (like the ladybug's leg pockets).
DiffusionCurveImage pocketImage() {
  DiffusionCurveImage image{128, 128, {}};
  DiffusionCurve circle = circleCurve(Point2(30.3, 30.2), 18.0, Color(1, 0, 0), Color(0, 0.8, 0.2));
  circle.left_colors = {{0.0, Color(0, 0.8, 0.2)}, {2.0, Color(1, 1, 0)}, {4.0, Color(0, 0, 1)}};
  image.curves.push_back(circle);
  const Point2 a(30.2, 118.1), b(118.3, 30.4), offset(3.6, 3.6);
  const Point2 gap = a + 0.2 * (b - a), gap_end = gap + 0.9 * (b - a).normalized();
  image.curves.push_back(barrier(a, gap));
  image.curves.push_back(barrier(gap_end, b));
  image.curves.push_back(barrier(b, b + offset));
  image.curves.push_back(barrier(b + offset, a + offset));
  image.curves.push_back(barrier(a + offset, a));
  return image;
}

struct PocketSolve {
  MultigridReport report;
  std::vector<float> values;
};

PocketSolve solvePocket(const GridProblem& problem, bool deflation, bool record) {
  MultigridOptions options;
  options.deflation = deflation;
  options.record_residuals = record;
  // The deflation alone: with the local relaxation of the start as well, the pocket takes 9
  // iterations deflated and 8 without (docs/rendering.md).
  options.local_relaxation = 0;
  PocketSolve solve;
  solve.values = solveMultigrid(problem, options, &solve.report);
  return solve;
}

TEST(DeflationTest, ChannelBehindAOnePixelGapConvergesFasterToTheDirectSolve) {
  const DiffusionCurveImage image = pocketImage();
  const GridProblem problem =
      assembleColorProblem(image, image.width, image.height, 1.0, Color::Zero());
  const std::vector<float> direct = solveDirect(problem);
  const PocketSolve deflated = solvePocket(problem, true, false);
  const PocketSolve plain = solvePocket(problem, false, false);
  EXPECT_TRUE(deflated.report.converged);
  EXPECT_TRUE(plain.report.converged);
  EXPECT_LE(maxAbsoluteError(deflated.values, direct), deflated.report.error_estimates.back());
  EXPECT_LE(maxAbsoluteError(deflated.values, direct), MultigridOptions::kDefaultTolerance);
  // 8 against 9 iterations: the channel's constant is deflated, its slow variation along the
  // channel is not (a piece is a kTileSize square at most).
  EXPECT_LT(deflated.report.fine_cycles, plain.report.fine_cycles);
}

// The rms statistics are computed only when asked for, in another loop: same iterate.
TEST(DeflationTest, RecordingTheResidualsDoesNotChangeTheResult) {
  const DiffusionCurveImage image = pocketImage();
  const GridProblem problem =
      assembleColorProblem(image, image.width, image.height, 1.0, Color::Zero());
  const PocketSolve recorded = solvePocket(problem, true, true);
  const PocketSolve quiet = solvePocket(problem, true, false);
  EXPECT_EQ(recorded.report.fine_cycles, quiet.report.fine_cycles);
  EXPECT_EQ(recorded.report.residuals.size(), recorded.report.error_estimates.size());
  EXPECT_TRUE(quiet.report.residuals.empty());
  EXPECT_LE(maxAbsoluteError(recorded.values, quiet.values), 1e-7);
}

}  // namespace
}  // namespace vicc_glyphs
