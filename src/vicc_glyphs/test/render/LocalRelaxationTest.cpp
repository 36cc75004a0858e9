// Local relaxation of the finest level's start: the pixel squares around the seeds, and what it
// buys on a contour with sharp tips (fewer CG iterations to the same accuracy) and costs where
// the start has no bad spot (nothing: identical results).

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "direct_reference_solve.hpp"
#include "multigrid_local_relaxation.hpp"
#include "sample_images.hpp"
#include "vicc_glyphs/render/grid_problem.hpp"
#include "vicc_glyphs/render/multigrid.hpp"

namespace vicc_glyphs {
namespace {

using multigrid_detail::FineLevel;
using multigrid_detail::LocalRelaxationSet;

// 10 x 8 free pixels, fully linked, one Dirichlet pixel at (5, 4).
FineLevel smallLevel() {
  GridProblem problem = openGridProblem(10, 8, 1);
  problem.fixed[4 * problem.width + 5] = 1;
  FineLevel fine;
  multigrid_detail::makeFineLevel(problem, fine);
  return fine;
}

// The fine indices of the pixels in [x0, x1] x [y0, y1] (clipped to the grid), sorted; with
// `free_only` without the Dirichlet ones.
std::vector<int> square(const FineLevel& fine, int x0, int y0, int x1, int y1, bool free_only) {
  std::vector<int> pixels;
  for (int y = std::max(0, y0); y <= std::min(fine.height - 1, y1); ++y) {
    for (int x = std::max(0, x0); x <= std::min(fine.width - 1, x1); ++x) {
      const int p = fine.index(x, y);
      if (!free_only || fine.isFree(p)) pixels.push_back(p);
    }
  }
  return pixels;
}

std::vector<int> sortedUnion(std::vector<int> a, const std::vector<int>& b) {
  a.insert(a.end(), b.begin(), b.end());
  std::sort(a.begin(), a.end());
  a.erase(std::unique(a.begin(), a.end()), a.end());
  return a;
}

TEST(LocalRelaxationSetTest, SquaresAroundTheSeedsClippedToTheGridWithoutDirichletPixels) {
  const FineLevel fine = smallLevel();
  LocalRelaxationSet set;
  set.build(fine, {fine.index(0, 0), fine.index(5, 3)}, 1);
  EXPECT_EQ(set.pixels(),
            sortedUnion(square(fine, -1, -1, 1, 1, true), square(fine, 4, 2, 6, 4, true)));
  EXPECT_EQ(set.pixels().size(), 4u + 8u);  // (5, 4) is a Dirichlet pixel
  // The residual changes one pixel further out, Dirichlet pixels included.
  EXPECT_EQ(set.affected(),
            sortedUnion(square(fine, -2, -2, 2, 2, false), square(fine, 3, 1, 7, 5, false)));
}

TEST(LocalRelaxationSetTest, ABuildForgetsTheSeedsOfTheLastOne) {
  const FineLevel fine = smallLevel();
  LocalRelaxationSet set;
  set.build(fine, {fine.index(0, 0), fine.index(5, 3)}, 1);
  set.build(fine, {fine.index(9, 7)}, 0);
  EXPECT_EQ(set.pixels(), std::vector<int>{fine.index(9, 7)});
  EXPECT_EQ(set.affected(), square(fine, 8, 6, 9, 7, false));
  set.build(fine, {}, 2);
  EXPECT_TRUE(set.pixels().empty());
  EXPECT_TRUE(set.affected().empty());
}

struct Solve {
  MultigridReport report;
  std::vector<float> values;
};

Solve solve(const GridProblem& problem, int local_relaxation) {
  MultigridOptions options;
  options.local_relaxation = local_relaxation;
  Solve result;
  MultigridSolver().solve(problem, options, result.values, &result.report);
  return result;
}

TEST(LocalRelaxationTest, SharpTipsNeedFewerIterationsToTheSameAccuracy) {
  // 96 teeth at 512 px: the inner tips are wedges of one or two pixels that FMG's start gets
  // wrong. (Blunter tips, e.g. 24 teeth at 256 px, have no such spot since the rasteriser
  // gives each pixel the side of the crossing it meets first on its link.)
  const DiffusionCurveImage image = zigzagImage(512, 96, 0.2, 0.45);
  ASSERT_EQ(image.curves[0].segmentCount(), 192);
  const GridProblem problem = assembleColorProblem(image, 512, 512, 1.0, Color::Zero());
  const std::vector<float> direct = solveDirect(problem);
  const Solve without = solve(problem, 0), with = solve(problem, 2);
  ASSERT_TRUE(without.report.converged);
  ASSERT_TRUE(with.report.converged);
  EXPECT_LT(with.report.fine_cycles, without.report.fine_cycles);
  EXPECT_LT(maxAbsoluteError(with.values, direct), MultigridOptions::kDefaultTolerance);
  EXPECT_LT(maxAbsoluteError(without.values, direct), MultigridOptions::kDefaultTolerance);
}

TEST(LocalRelaxationTest, ASmoothStartIsLeftAlone) {
  // A circle's start has no spot above the seed threshold: the same result to the bit.
  const GridProblem problem =
      assembleColorProblem(circleImage(128, 128), 128, 128, 1.0, Color::Zero());
  const Solve without = solve(problem, 0), with = solve(problem, 2);
  EXPECT_EQ(with.report.fine_cycles, without.report.fine_cycles);
  EXPECT_EQ(with.values, without.values);
}

TEST(LocalRelaxationTest, NegativeSweepsAreRefused) {
  const GridProblem problem = assembleColorProblem(circleImage(32, 32), 32, 32, 1.0, Color::Zero());
  for (int MultigridOptions::*sweeps :
       {&MultigridOptions::local_relaxation, &MultigridOptions::isolated_spot_sweeps}) {
    MultigridOptions options;
    options.*sweeps = -1;
    std::vector<float> values;
    EXPECT_THROW(MultigridSolver().solve(problem, options, values, nullptr), std::invalid_argument);
  }
}

}  // namespace
}  // namespace vicc_glyphs
