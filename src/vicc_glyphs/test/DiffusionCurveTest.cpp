#include <gtest/gtest.h>

#include <limits>

#include "vicc_glyphs/dci/diffusion_curve.hpp"

namespace vicc_glyphs {
namespace {

DiffusionCurve straightLine() {
  DiffusionCurve curve;
  curve.control_points = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {5, 0}, {6, 0}};
  curve.left_colors = {{0.0, Color(1, 0, 0)}, {2.0, Color(0, 0, 1)}};
  curve.right_colors = {{1.0, Color(0, 1, 0)}};
  return curve;
}

TEST(DiffusionCurveTest, EvaluatesSegmentsByCurveParameter) {
  const DiffusionCurve curve = straightLine();
  ASSERT_EQ(curve.segmentCount(), 2);
  EXPECT_NEAR(curve.pointAt(0.5).x(), 1.5, 1e-12);
  EXPECT_NEAR(curve.pointAt(1.5).x(), 4.5, 1e-12);
  EXPECT_NEAR(curve.pointAt(7.0).x(), 6.0, 1e-12);  // clamped to the end
  EXPECT_NEAR(curve.derivativeAt(1.25).x(), 3.0, 1e-12);
}

TEST(DiffusionCurveTest, InterpolatesColoursAndHoldsThemBeyondTheEnds) {
  const DiffusionCurve curve = straightLine();
  EXPECT_TRUE(curve.leftColorAt(1.0).isApprox(Color(0.5, 0, 0.5)));
  EXPECT_TRUE(curve.leftColorAt(2.0).isApprox(Color(0, 0, 1)));
  EXPECT_TRUE(curve.rightColorAt(0.0).isApprox(Color(0, 1, 0)));
  EXPECT_DOUBLE_EQ(curve.blurAt(1.0), 0.0);
}

TEST(DiffusionCurveTest, ValidationNamesTheProblem) {
  DiffusionCurveImage image{10, 10, {straightLine()}};
  EXPECT_EQ(validate(image), "");
  image.curves[0].control_points.pop_back();
  EXPECT_NE(validate(image).find("3K+1"), std::string::npos);
  image.curves[0] = straightLine();
  image.curves[0].control_points[2].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(validate(image).find("non-finite"), std::string::npos);
  image.curves[0] = straightLine();
  image.curves[0].left_colors[0].rgb[1] = 2.0;
  EXPECT_NE(validate(image).find("outside [0, 1]"), std::string::npos);
}

TEST(DiffusionCurveTest, ScalingKeepsAspectAndScalesGeometry) {
  DiffusionCurveImage image{100, 50, {straightLine()}};
  const DiffusionCurveImage scaled = scaledToWidth(image, 200);
  EXPECT_EQ(scaled.width, 200);
  EXPECT_EQ(scaled.height, 100);
  EXPECT_NEAR(scaled.curves[0].control_points.back().x(), 12.0, 1e-12);
}

}  // namespace
}  // namespace vicc_glyphs
