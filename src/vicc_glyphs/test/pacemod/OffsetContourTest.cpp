#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "vicc_glyphs/pacemod/offset_contour.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

Polyline circlePolygon(double radius, bool clockwise) {
  Polyline line;
  for (int i = 0; i <= 720; ++i) {
    const double angle = (clockwise ? 1 : -1) * 2 * M_PI * i / 720;
    line.emplace_back(100 + radius * std::cos(angle), 100 + radius * std::sin(angle));
  }
  line.back() = line.front();
  return line;
}

void expectRadius(const Polyline& line, double radius, double tolerance) {
  ASSERT_GT(line.size(), 10u);
  for (const Point2& p : line) EXPECT_NEAR((p - Point2(100, 100)).norm(), radius, tolerance);
}

TEST(OffsetContourTest, IsolinesOfACircleAreConcentricCirclesWithTheSameOrientation) {
  for (bool clockwise : {true, false}) {
    const Polyline circle = circlePolygon(40, clockwise);
    const Polyline inflated = offsetIsoline(circle, 6.0);
    expectRadius(inflated, 46.0, 0.3);
    const Polyline shrunk = offsetIsoline(circle, -10.0);
    expectRadius(shrunk, 30.0, 0.3);
    expectRadius(offsetIsoline(circle, 0.0), 40.0, 0.3);  // the region itself
    EXPECT_EQ(polylineArea(inflated) > 0, polylineArea(circle) > 0);
    EXPECT_EQ(polylineArea(shrunk) > 0, polylineArea(circle) > 0);
  }
}

// One distance field for several insets of one contour: the same isolines as offsetIsoline.
TEST(OffsetContourTest, InsideDistanceGivesOffsetIsolinesInsideFromOneField) {
  const Polyline circle = circlePolygon(40, true);
  const InsideDistance inside(circle);
  for (double offset : {0.0, -3.0, -10.0, -25.5}) {
    EXPECT_EQ(inside.isoline(offset), offsetIsoline(circle, offset)) << offset;
  }
  expectRadius(inside.isoline(-10.0), 30.0, 0.3);
  EXPECT_TRUE(inside.isoline(-45.0).empty());
  EXPECT_THROW(inside.isoline(1.0), std::invalid_argument);
  EXPECT_TRUE(InsideDistance({}).isoline(-1.0).empty());
}

TEST(OffsetContourTest, ShrinkingPastTheRegionLeavesNothing) {
  EXPECT_TRUE(offsetIsoline(circlePolygon(10, true), -12.0).empty());
  EXPECT_TRUE(offsetIsoline({}, 1.0).empty());
}

TEST(OffsetContourTest, ClosedBezierFitIsAClosedChainOnTheLine) {
  const std::vector<Point2> chain = closedBezierFit(circlePolygon(40, true));
  ASSERT_EQ((chain.size() - 1) % 3, 0u);
  EXPECT_LT((chain.front() - chain.back()).norm(), 1e-9);
  DiffusionCurve curve;
  curve.control_points = chain;
  for (const Point2& p : sampleCurve(curve, 8)) {
    EXPECT_NEAR((p - Point2(100, 100)).norm(), 40.0, 0.05);
  }
  EXPECT_THROW(closedBezierFit({{0, 0}, {1, 0}, {0, 0}}), std::invalid_argument);
}

}  // namespace
}  // namespace pacemod
}  // namespace vicc_glyphs
