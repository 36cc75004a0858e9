// Local relaxation of the finest level's start: the pixel squares around the seeds, and what it
// buys on a contour with sharp tips (fewer CG iterations to the same accuracy) and costs where
// the start has no bad spot (nothing: identical results).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

// A closed zigzag (a star of `teeth` sharp tips, radii 0.25 and 0.4 of the size), orange
// inside, dark blue outside: every tip is a wedge of one or two pixels that FMG's start gets
// wrong by up to 0.1-0.2.
DiffusionCurveImage zigzagImage(int size, int teeth) {
  DiffusionCurveImage image;
  image.width = image.height = size;
  const Point2 centre(size / 2.0, size / 2.0);
  std::vector<Point2> corners;
  for (int k = 0; k < 2 * teeth; ++k) {
    const double angle = M_PI * k / teeth, radius = size * (k % 2 ? 0.4 : 0.25);
    corners.push_back(centre + radius * Point2(std::cos(angle), std::sin(angle)));
  }
  // Clockwise on screen (angles grow in the y-down frame): the inside is the right side.
  DiffusionCurve curve;
  curve.control_points = {corners[0]};
  for (size_t k = 1; k <= corners.size(); ++k) {
    const Point2 from = corners[k - 1], to = corners[k % corners.size()];
    curve.control_points.insert(curve.control_points.end(),
                                {from + (to - from) / 3.0, from + 2.0 * (to - from) / 3.0, to});
  }
  curve.left_colors = {{0.0, Color(0.05, 0.1, 0.4)}};
  curve.right_colors = {{0.0, Color(1.0, 0.6, 0.1)}};
  image.curves.push_back(curve);
  return image;
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
  const DiffusionCurveImage image = zigzagImage(256, 24);
  ASSERT_EQ(image.curves[0].segmentCount(), 48);
  const GridProblem problem = assembleColorProblem(image, 256, 256, 1.0, Color::Zero());
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
  MultigridOptions options;
  options.local_relaxation = -1;
  std::vector<float> values;
  EXPECT_THROW(MultigridSolver().solve(problem, options, values, nullptr), std::invalid_argument);
}

}  // namespace
}  // namespace vicc_glyphs
