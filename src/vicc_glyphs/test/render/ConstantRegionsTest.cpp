#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "direct_reference_solve.hpp"
#include "sample_images.hpp"
#include "vicc_glyphs/io/load.hpp"
#include "vicc_glyphs/render/constant_regions.hpp"
#include "vicc_glyphs/render/multigrid.hpp"
#include "vicc_glyphs/render/renderer.hpp"

namespace vicc_glyphs {
namespace {

GridProblem colorProblem(const DiffusionCurveImage& image) {
  return assembleColorProblem(image, image.width, image.height, 1.0, Color::Zero());
}

// A width x height single-channel grid with every link inside it and no Dirichlet pixel.
GridProblem linkedGrid(int width, int height) {
  GridProblem problem;
  problem.width = width;
  problem.height = height;
  problem.channels = 1;
  const int n = width * height;
  problem.couples_right.assign(n, 1);
  problem.couples_down.assign(n, 1);
  for (int y = 0; y < height; ++y) problem.couples_right[y * width + width - 1] = 0;
  for (int x = 0; x < width; ++x) problem.couples_down[(height - 1) * width + x] = 0;
  problem.fixed.assign(n, 0);
  problem.values.assign(n, 0.0f);
  return problem;
}

void fix(GridProblem& problem, int x, int y, float value) {
  problem.fixed[y * problem.width + x] = 1;
  problem.values[y * problem.width + x] = value;
}

// Cuts the links between columns x and x + 1 in every row: two regions.
void cutColumns(GridProblem& problem, int x) {
  for (int y = 0; y < problem.height; ++y) problem.couples_right[y * problem.width + x] = 0;
}

std::vector<float> solve(const GridProblem& problem, bool* constant) {
  std::vector<float> values(problem.values.size(), -1.0f);
  *constant = ConstantRegions().solve(problem, ConstantRegions::kDefaultSpread, values.data());
  return values;
}

TEST(ConstantRegionsTest, EachRegionTakesItsOwnDirichletValue) {
  GridProblem problem = linkedGrid(6, 3);
  cutColumns(problem, 2);
  fix(problem, 0, 0, 0.25f);
  fix(problem, 1, 2, 0.25f);
  fix(problem, 5, 1, 0.75f);
  bool constant = false;
  const std::vector<float> values = solve(problem, &constant);
  ASSERT_TRUE(constant);
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 6; ++x) {
      EXPECT_FLOAT_EQ(values[y * 6 + x], x <= 2 ? 0.25f : 0.75f) << x << ", " << y;
    }
  }
  // The same as the direct solve of the equations.
  EXPECT_LT(maxAbsoluteError(values, solveDirect(problem)), 1e-6);
}

TEST(ConstantRegionsTest, ARegionSeeingTwoValuesIsNotConstant) {
  GridProblem problem = linkedGrid(5, 4);
  fix(problem, 0, 0, 0.2f);
  fix(problem, 4, 3, 0.3f);
  bool constant = true;
  solve(problem, &constant);
  EXPECT_FALSE(constant);
  // Separated by a cut, the two values are two constant regions.
  cutColumns(problem, 1);
  solve(problem, &constant);
  EXPECT_TRUE(constant);
}

// A corridor that turns twice: its Dirichlet pixel at the bottom left reaches the top row's
// right part only by going right, up, left, up and right again, which neither raster pass
// does; the search after them does.
TEST(ConstantRegionsTest, ARegionThatTheRasterPassesCannotFillIsSearched) {
  GridProblem problem = linkedGrid(4, 3);
  for (int x = 1; x < 4; ++x) problem.couples_down[x] = 0;      // rows 0 and 1 meet at x = 0
  for (int x = 0; x < 3; ++x) problem.couples_down[4 + x] = 0;  // rows 1 and 2 at x = 3
  fix(problem, 0, 2, 0.75f);
  bool constant = false;
  const std::vector<float> values = solve(problem, &constant);
  ASSERT_TRUE(constant);
  for (int p = 0; p < 12; ++p) EXPECT_EQ(values[p], 0.75f) << p;
  // The same corridor with a second value at its other end is not constant.
  fix(problem, 3, 0, 0.25f);
  solve(problem, &constant);
  EXPECT_FALSE(constant);
}

TEST(ConstantRegionsTest, ValuesWithinHalfTheSpreadShareTheFirstOfThem) {
  GridProblem problem = linkedGrid(4, 4);
  const float low = 0.5f, high = 0.5f + 0.4f * ConstantRegions::kDefaultSpread;
  fix(problem, 0, 0, low);
  fix(problem, 3, 3, high);
  bool constant = false;
  const std::vector<float> values = solve(problem, &constant);
  ASSERT_TRUE(constant);
  EXPECT_EQ(values[5], low);
  EXPECT_EQ(values[15], high);  // Dirichlet pixels keep their values
  // The exact solution lies between them (maximum principle).
  EXPECT_LE(maxAbsoluteError(values, solveDirect(problem)), high - low);
  problem.values[15] = 0.5f + ConstantRegions::kDefaultSpread;
  solve(problem, &constant);
  EXPECT_FALSE(constant);
}

// Beyond kMaxColors distinct values the problem is taken for a gradient, even if its regions
// are flat.
TEST(ConstantRegionsTest, TooManyColoursAreLeftToTheSolver) {
  const int count = static_cast<int>(ConstantRegions::kMaxColors);
  GridProblem problem = linkedGrid(2 * (count + 1), 2);
  for (int k = 0; k <= count; ++k) {
    cutColumns(problem, 2 * k + 1);
    fix(problem, 2 * k, 0, 0.01f * static_cast<float>(k));
  }
  bool constant = true;
  solve(problem, &constant);
  EXPECT_FALSE(constant);
  problem.values[0] = 0.01f;  // k = 0 and k = 1 share a colour: kMaxColors in all
  const std::vector<float> values = solve(problem, &constant);
  EXPECT_TRUE(constant);
  EXPECT_EQ(values[problem.width + 1], 0.01f);
  EXPECT_EQ(values[problem.width + 2 * count + 1], 0.01f * static_cast<float>(count));
}

TEST(ConstantRegionsTest, RegionsWithoutDirichletPixelsOrLinksLeavingTheGridAreLeftToTheSolver) {
  GridProblem problem = linkedGrid(6, 3);
  cutColumns(problem, 2);
  fix(problem, 0, 0, 0.25f);  // the right region has none: singular on its own
  bool constant = true;
  solve(problem, &constant);
  EXPECT_FALSE(constant);

  GridProblem leaving = linkedGrid(6, 3);
  fix(leaving, 0, 0, 0.25f);
  leaving.couples_right[5] = 1;  // from the last column out of the grid
  solve(leaving, &constant);
  EXPECT_FALSE(constant);
  leaving.couples_right[5] = 0;
  leaving.couples_down[2 * 6 + 3] = 1;  // from the last row
  solve(leaving, &constant);
  EXPECT_FALSE(constant);
  leaving.couples_down[2 * 6 + 3] = 0;
  solve(leaving, &constant);
  EXPECT_TRUE(constant);
}

// The samples with one colour per region skip the multigrid and match the direct solve far
// closer than its tolerance; those whose colours diffuse are iterated.
TEST(ConstantRegionsTest, TheSolverSkipsTheMultigridExactlyForFlatRegions) {
  for (const DiffusionCurveImage& image :
       {circleImage(201, 157), barrierImage(192, 128), twoColourLineImage(160, 120)}) {
    const GridProblem problem = colorProblem(image);
    MultigridReport report;
    const std::vector<float> values = solveMultigrid(problem, {}, &report);
    EXPECT_TRUE(report.constant_regions);
    EXPECT_TRUE(report.converged);
    EXPECT_EQ(report.levels, 0);
    EXPECT_LT(maxAbsoluteError(values, solveDirect(problem)), 1e-5);
  }
  for (const DiffusionCurveImage& image :
       {gradientCircleImage(200, 200), iconLikeImage(256, 256)}) {
    MultigridReport report;
    solveMultigrid(colorProblem(image), {}, &report);
    EXPECT_FALSE(report.constant_regions);
    EXPECT_GT(report.levels, 4);
  }
  // A fixed iteration count iterates whatever the problem.
  MultigridOptions counted;
  counted.tolerance = 0.0;
  counted.fine_cycles = 1;
  MultigridReport report;
  solveMultigrid(colorProblem(circleImage(201, 157)), counted, &report);
  EXPECT_FALSE(report.constant_regions);
  EXPECT_GT(report.levels, 4);
}

// A flat icon at 512 px: the picture the multigrid gives within its tolerance, now exact.
TEST(ConstantRegionsTest, AFlatIconRendersAsTheMultigridRendersIt) {
  const DiffusionCurveImage icon =
      loadDiffusionCurves(std::string(VICC_GLYPHS_DATA_DIR) + "/icons/heart.svg", 512);
  DiffusionCurveRenderer renderer;
  RenderOptions options;
  RenderResult exact, iterated;
  renderer.render(icon, options, exact);
  options.multigrid.constant_regions = false;
  renderer.render(icon, options, iterated);
  EXPECT_TRUE(exact.report.multigrid.constant_regions);
  EXPECT_FALSE(iterated.report.multigrid.constant_regions);
  ASSERT_EQ(exact.image.size(), iterated.image.size());
  cv::Mat difference;
  cv::absdiff(exact.image, iterated.image, difference);
  double largest = 0.0;
  cv::minMaxLoc(difference.reshape(1), nullptr, &largest);
  EXPECT_LT(largest, MultigridOptions::kDefaultTolerance);
  cv::Mat exact8, iterated8;
  exact.image.convertTo(exact8, CV_8UC3, 255.0);
  iterated.image.convertTo(iterated8, CV_8UC3, 255.0);
  EXPECT_EQ(cv::norm(exact8, iterated8, cv::NORM_INF), 0.0);
}

}  // namespace
}  // namespace vicc_glyphs
