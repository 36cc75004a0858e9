#include <gtest/gtest.h>

#include "sample_images.hpp"
#include "vicc_glyphs/render/grid_problem.hpp"

namespace vicc_glyphs {
namespace {

TEST(GridProblemTest, LineCutsLinksAndFixesBothSides) {
  // Upward line at x = 4.5 + 0.3: between pixel columns 4 and 5 (centres 4.5 and 5.5).
  DiffusionCurveImage image{10, 6, {}};
  image.curves.push_back(lineCurve({4.8, 8}, {4.8, -2}, Color(1, 0, 0), Color(0, 0, 1)));
  const GridProblem problem = assembleColorProblem(image, 10, 6, 1.0, Color::Zero());
  for (int y = 0; y < 6; ++y) {
    const int left = y * 10 + 4, right = y * 10 + 5;
    EXPECT_EQ(problem.couples_right[left], 0) << y;
    EXPECT_EQ(problem.couples_right[left - 1], 1) << y;
    EXPECT_EQ(problem.fixed[left], 1);
    EXPECT_EQ(problem.fixed[right], 1);
    EXPECT_EQ(problem.fixed[left - 1], 0);
    EXPECT_FLOAT_EQ(problem.value(0, left), 1.0f);  // red on the left (screen left: upward)
    EXPECT_FLOAT_EQ(problem.value(2, right), 1.0f);
    EXPECT_EQ(problem.couples_right[y * 10 + 9], 0);  // Neumann border
  }
  for (int x = 0; x < 10; ++x) EXPECT_EQ(problem.couples_down[5 * 10 + x], 0);
}

TEST(GridProblemTest, BarrierSideCutsLinksWithoutColour) {
  DiffusionCurveImage image{10, 6, {}};
  DiffusionCurve line = lineCurve({4.8, 8}, {4.8, -2}, Color(1, 0, 0), Color(0, 0, 1));
  line.right_emits = false;
  image.curves.push_back(line);
  const GridProblem problem = assembleColorProblem(image, 10, 6, 1.0, Color::Zero());
  EXPECT_EQ(problem.couples_right[4], 0);
  EXPECT_EQ(problem.fixed[4], 1);
  EXPECT_EQ(problem.fixed[5], 1);  // unreached right half: fixed to the background
  EXPECT_FLOAT_EQ(problem.value(2, 5), 0.0f);
}

TEST(GridProblemTest, PixelsNoDirichletPixelReachesTakeTheBackground) {
  const DiffusionCurveImage image{8, 8, {}};
  const GridProblem problem = assembleColorProblem(image, 8, 8, 1.0, Color(0.2, 0.4, 0.6));
  for (int p = 0; p < problem.pixelCount(); ++p) {
    ASSERT_EQ(problem.fixed[p], 1);
    EXPECT_FLOAT_EQ(problem.value(1, p), 0.4f);
  }
}

TEST(GridProblemTest, ThinWedgeTipTakesTheNearestSideNotAMix) {
  // A closed, thin wedge (white inside, red outside) whose tip is narrower than a pixel over
  // several columns: links there are crossed twice, once by each flank.
  const Point2 corners[] = {{5, 8}, {30.2, 10.25}, {5, 12.5}, {5, 8}};
  DiffusionCurve wedge;
  for (int k = 0; k < 3; ++k) {
    const Point2 a = corners[k], b = corners[k + 1];
    if (k == 0) wedge.control_points.push_back(a);
    wedge.control_points.insert(wedge.control_points.end(),
                                {a + (b - a) / 3.0, a + 2.0 * (b - a) / 3.0, b});
  }
  wedge.left_colors = {{0.0, Color(1, 0, 0)}};  // clockwise on screen: left is outside
  wedge.right_colors = {{0.0, Color(1, 1, 1)}};
  DiffusionCurveImage image{40, 20, {wedge}};
  const GridProblem problem = assembleColorProblem(image, 40, 20, 1.0, Color::Zero());
  int fixed = 0;
  for (int p = 0; p < problem.pixelCount(); ++p) {
    if (!problem.fixed[p]) continue;
    ++fixed;
    const float green = problem.value(1, p);
    EXPECT_TRUE(green == 0.0f || green == 1.0f) << "pixel " << p % 40 << "," << p / 40;
  }
  EXPECT_GT(fixed, 40);
}

TEST(GridProblemTest, BlurProblemCarriesScaledSigmaOnBothSides) {
  DiffusionCurveImage image{10, 6, {}};
  DiffusionCurve line = lineCurve({4.8, 8}, {4.8, -2}, Color(1, 0, 0), Color(0, 0, 1));
  line.blur_points = {{0.0, 4.0}};
  image.curves.push_back(line);
  const GridProblem problem = assembleBlurProblem(image, 10, 6, 0.5);
  ASSERT_EQ(problem.channels, 1);
  EXPECT_FLOAT_EQ(problem.value(0, 2 * 10 + 2), 2.0f);  // x = 2.4 on the half-scale grid
  EXPECT_FLOAT_EQ(problem.value(0, 2 * 10 + 1), 2.0f);
}

}  // namespace
}  // namespace vicc_glyphs
