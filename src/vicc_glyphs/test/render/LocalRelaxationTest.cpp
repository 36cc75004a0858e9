// Local relaxation of the finest level's start: the pixel squares around the seeds, and what it
// buys at the ends of an open curve (fewer CG iterations to the same accuracy) and costs where
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
  options.constant_regions = false;  // the solver's own path, whatever the colours
  Solve result;
  MultigridSolver().solve(problem, options, result.values, &result.report);
  return result;
}

TEST(LocalRelaxationTest, CurveEndsNeedFewerIterationsToTheSameAccuracy) {
  // An open curve, red on one side and blue on the other, ending inside the image: around its
  // ends the solution turns from one colour to the other within a pixel or two, which FMG's
  // start (P cannot represent it) gets wrong. (Until session 43 a zigzag's sharp tips showed
  // this too; their bad spots were pixels given the mean of both sides' colours where a tip
  // touched a line of pixel centres, a touch the rasteriser now leaves uncut.)
  DiffusionCurveImage image;
  image.width = 512;
  image.height = 512;
  image.curves.push_back(
      lineCurve({100.3, 256.2}, {400.7, 256.9}, Color(1.0, 0.0, 0.0), Color(0.0, 0.0, 1.0)));
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
