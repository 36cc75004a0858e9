#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../support/straight_chain.hpp"
#include "vicc_glyphs/pacemod/contour_teeth.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

DiffusionCurve straightChain(const std::vector<Point2>& corners) {
  DiffusionCurve curve;
  curve.control_points = test::closedStraightChain(corners);
  return curve;
}

Point2 unit(const Point2& d) { return d.normalized(); }

// The top side steps 0.2 px down and on (segment 1, like MDI's `V13.73`): one point at the
// middle of the step, the sides' handles still along the sides.
TEST(ContourTeethTest, AStepBackAndForthBecomesOnePoint) {
  DiffusionCurve curve =
      straightChain({{20, 20}, {120, 20}, {120, 20.2}, {220, 20.2}, {220, 220}, {20, 220}});
  curve.left_colors = {{0.5, Color(1, 0, 0)}, {1.5, Color(0, 1, 0)}, {2.5, Color(0, 0, 1)}};
  curve.blur_points = {{4.0, 1.0}};
  const DiffusionCurve clean = withoutTeeth(curve);
  ASSERT_EQ(clean.segmentCount(), curve.segmentCount() - 1);
  const std::vector<Point2>& p = clean.control_points;
  EXPECT_NEAR((p[3] - Point2(120, 20.1)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((unit(p[3] - p[2]) - Point2(1, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((unit(p[4] - p[3]) - Point2(1, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((p[6] - Point2(220, 20.2)).norm(), 0.0, 1e-12);  // the rest stays
  EXPECT_NEAR((p.front() - p.back()).norm(), 0.0, 1e-12);
  ASSERT_EQ(clean.left_colors.size(), 3u);
  EXPECT_DOUBLE_EQ(clean.left_colors[0].position, 0.5);
  EXPECT_DOUBLE_EQ(clean.left_colors[1].position, 1.0);  // on the step: at its place
  EXPECT_DOUBLE_EQ(clean.left_colors[2].position, 1.5);
  EXPECT_DOUBLE_EQ(clean.blur_points[0].position, 3.0);
}

// Two 45-degree joins 0.3 px apart (a bevel too small to see) become one 90-degree corner.
TEST(ContourTeethTest, ASubPixelBevelBecomesOneCorner) {
  const DiffusionCurve curve =
      straightChain({{20, 20}, {120, 20}, {120.2, 20.2}, {120.2, 120}, {20, 120}});
  const DiffusionCurve clean = withoutTeeth(curve);
  ASSERT_EQ(clean.segmentCount(), curve.segmentCount() - 1);
  const std::vector<Point2>& p = clean.control_points;
  EXPECT_NEAR((p[3] - Point2(120.1, 20.1)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(unit(p[3] - p[2]).dot(unit(p[4] - p[3])), 0.0, 1e-12);
}

TEST(ContourTeethTest, LongerStepsSmoothJoinsAndTheSeamStay) {
  // A step of 1 px is a feature of the icon.
  const DiffusionCurve step =
      straightChain({{20, 20}, {120, 20}, {120, 21}, {220, 21}, {220, 220}, {20, 220}});
  EXPECT_EQ(withoutTeeth(step).control_points, step.control_points);
  // A short piece of a straight side: no sharp join.
  const DiffusionCurve split =
      straightChain({{20, 20}, {120, 20}, {120.3, 20}, {220, 20}, {220, 220}, {20, 220}});
  EXPECT_EQ(withoutTeeth(split).control_points, split.control_points);
  // A circle of radius 4.6 px as 72 sides of 0.4 px, each turning by 5 degrees: a shape.
  std::vector<Point2> circle;
  for (int k = 0; k < 72; ++k) {
    circle.emplace_back(50 + 4.6 * std::cos(k * M_PI / 36), 50 + 4.6 * std::sin(k * M_PI / 36));
  }
  const DiffusionCurve fine = straightChain(circle);
  EXPECT_EQ(withoutTeeth(fine).control_points, fine.control_points);
  // The first segment is the step: left alone (the seam of the closed curve).
  const DiffusionCurve seam =
      straightChain({{120, 20}, {120, 20.2}, {220, 20.2}, {220, 220}, {20, 220}, {20, 20}});
  EXPECT_EQ(withoutTeeth(seam).control_points, seam.control_points);
}

}  // namespace
}  // namespace pacemod
}  // namespace vicc_glyphs
