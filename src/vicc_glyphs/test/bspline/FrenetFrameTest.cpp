#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "vicc_glyphs/bspline/bezier_conversion.hpp"
#include "vicc_glyphs/bspline/frenet_frame.hpp"

namespace vicc_glyphs {
namespace bspline {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Circle of radius r around c from 16 cubic Bezier arcs (handle length 4/3 tan(angle / 4) r;
// curvature within ~1e-4 of 1 / r), clockwise or counter-clockwise as seen on screen (y down):
// increasing angle runs from +x towards +y, i.e. clockwise on screen.
BSplineCurve circle(const Point2& c, double r, bool clockwise_on_screen) {
  const int arcs = 16;
  const double step = 2 * kPi / arcs;
  const double handle = 4.0 / 3.0 * std::tan(step / 4) * r;
  std::vector<Point2> points;
  for (int i = 0; i < arcs; ++i) {
    const Point2 radial0(std::cos(i * step), std::sin(i * step));
    const Point2 radial1(std::cos((i + 1) * step), std::sin((i + 1) * step));
    const Point2 tangent0(-radial0.y(), radial0.x());
    const Point2 tangent1(-radial1.y(), radial1.x());
    points.push_back(c + r * radial0);
    points.push_back(c + r * radial0 + handle * tangent0);
    points.push_back(c + r * radial1 - handle * tangent1);
  }
  points.push_back(points.front());
  if (!clockwise_on_screen) std::reverse(points.begin(), points.end());
  return bezierChainToBSpline(points).curve;
}

TEST(FrenetFrameTest, CircleHasCurvatureOneOverRadiusAndNormalsTowardsTheCentre) {
  const Point2 centre(50, 40);
  const double radius = 10.0;
  for (bool clockwise : {true, false}) {
    const BSplineCurve curve = circle(centre, radius, clockwise);
    for (double u = 0.05; u < 16.0; u += 0.37) {
      const FrenetFrame frame = frenetFrameAt(curve, u);
      EXPECT_NEAR(std::abs(frame.curvature), 1.0 / radius, 1e-3 / radius) << u;
      const Point2 to_centre = (centre - frame.position).normalized();
      EXPECT_GT(frame.normal.dot(to_centre), 0.999) << u;
      EXPECT_NEAR(frame.tangent.norm(), 1.0, 1e-12);
      EXPECT_NEAR(frame.tangent.dot(frame.normal), 0.0, 1e-12);
      EXPECT_GT(inwardNormalAt(curve, u).dot(to_centre), 0.999) << u;
      EXPECT_EQ(inwardNormalAt(curve, u, signedArea(curve)), inwardNormalAt(curve, u));
    }
    // Clockwise on screen turns right, i.e. away from the left normal: negative curvature.
    EXPECT_EQ(frenetFrameAt(curve, 1.3).curvature < 0.0, clockwise);
    EXPECT_NEAR(std::abs(signedArea(curve)), kPi * radius * radius, 0.01 * radius * radius);
    EXPECT_EQ(signedArea(curve) > 0.0, clockwise);
  }
}

TEST(FrenetFrameTest, LeftNormalFollowsTheImageConvention) {
  // Walking along +x on screen, "left" is up, which is -y in the y-down frame.
  const BSplineCurve line(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 5}, {1, 5}, {2, 5}, {3, 5}});
  EXPECT_LT((leftNormalAt(line, 0.5) - Point2(0, -1)).norm(), 1e-12);
  const FrenetFrame straight = frenetFrameAt(line, 0.5);
  EXPECT_DOUBLE_EQ(straight.curvature, 0.0);
  EXPECT_LT((straight.normal - Point2(0, -1)).norm(), 1e-12);

  // A valley on screen (dipping towards +y) walked to the right turns left: its centre of
  // curvature lies above, on the left normal's side. A hill turns right.
  const BSplineCurve valley(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 5}, {1, 6}, {2, 6}, {3, 5}});
  EXPECT_GT(signedCurvatureAt(valley, 0.5), 0.0);
  EXPECT_LT((frenetFrameAt(valley, 0.5).normal - Point2(0, -1)).norm(), 1e-12);
  const BSplineCurve hill(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 5}, {1, 4}, {2, 4}, {3, 5}});
  EXPECT_LT(signedCurvatureAt(hill, 0.5), 0.0);
  EXPECT_LT((frenetFrameAt(hill, 0.5).normal - Point2(0, 1)).norm(), 1e-12);
}

TEST(FrenetFrameTest, CurvatureMatchesTheClosedFormOfAParabola) {
  // y = x^2 as a Bezier with x = u: s' = (1, 2u), s'' = (0, 2).
  const BSplineCurve parabola(3, {0, 0, 0, 0, 1, 1, 1, 1},
                              {{0, 0}, {1.0 / 3, 0}, {2.0 / 3, 1.0 / 3}, {1, 1}});
  for (double u : {0.0, 0.25, 0.5, 1.0}) {
    const double expected = 2.0 / std::pow(1.0 + 4.0 * u * u, 1.5);
    // y grows downwards on screen while x grows: the curve turns right, away from the left
    // normal (dy, -dx), so the signed curvature is negative.
    EXPECT_NEAR(signedCurvatureAt(parabola, u), -expected, 1e-12) << u;
  }
}

TEST(FrenetFrameTest, VanishingDerivativeIsRejected) {
  const BSplineCurve point(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{1, 1}, {1, 1}, {1, 1}, {1, 1}});
  EXPECT_THROW(frenetFrameAt(point, 0.5), std::invalid_argument);
  EXPECT_THROW(leftNormalAt(point, 0.5), std::invalid_argument);
  EXPECT_THROW(inwardNormalAt(point, 0.5), std::invalid_argument);
  const BSplineCurve line(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0}, {1, 0}, {2, 0}, {3, 0}});
  EXPECT_DOUBLE_EQ(signedArea(line), 0.0);
  EXPECT_THROW(inwardNormalAt(line, 0.5), std::invalid_argument);
}

}  // namespace
}  // namespace bspline
}  // namespace vicc_glyphs
