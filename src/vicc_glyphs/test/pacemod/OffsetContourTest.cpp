#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

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
    expectRadius(inflated, 46.0, 0.02);  // the circle is a 720-gon: its edges are 0.015 px in
    const Polyline shrunk = offsetIsoline(circle, -10.0);
    expectRadius(shrunk, 30.0, 0.02);
    expectRadius(offsetIsoline(circle, 0.0), 40.0, 0.02);  // the region itself
    EXPECT_EQ(polylineArea(inflated) > 0, polylineArea(circle) > 0);
    EXPECT_EQ(polylineArea(shrunk) > 0, polylineArea(circle) > 0);
  }
}

Polyline scaled(Polyline line, double factor) {
  for (Point2& p : line) p *= factor;
  return line;
}

// A five-lobed flower (smooth, with tight concave bends) and a cross (convex and reflex
// corners): every point of an isoline lies at the offset from the contour, whether the isoline
// has corners (a cross shrunk, the flower inflated past its bends' radii) or arcs. At 4x the
// size the raster's cells are 2 px: its points are 2 px apart, and the 2 px arcs around the
// cross's corners need points in between.
TEST(OffsetContourTest, IsolinePointsLieAtTheOffsetFromTheContour) {
  Polyline flower;
  for (int i = 0; i <= 1000; ++i) {
    const double angle = 2 * M_PI * i / 1000, radius = 60 + 25 * std::cos(5 * angle);
    flower.emplace_back(150 + radius * std::cos(angle), 150 + radius * std::sin(angle));
  }
  flower.back() = flower.front();
  const Polyline cross = {{100, 50},  {140, 50},  {140, 100}, {190, 100}, {190, 140},
                          {140, 140}, {140, 190}, {100, 190}, {100, 140}, {50, 140},
                          {50, 100},  {100, 100}, {100, 50}};
  const std::vector<Polyline> contours{flower, cross, scaled(flower, 4.0), scaled(cross, 4.0)};
  for (std::size_t c = 0; c < contours.size(); ++c) {
    SCOPED_TRACE("contour " + std::to_string(c));
    const Polyline& contour = contours[c];
    for (double offset : {-12.0, -3.0, 0.0, 2.0, 8.0}) {
      const Polyline isoline = offsetIsoline(contour, offset);
      ASSERT_GT(isoline.size(), 100u) << offset;
      EXPECT_LT((isoline.front() - isoline.back()).norm(), 1e-12);
      double largest_gap = 0.0, smallest_gap = 1e300;
      for (std::size_t i = 0; i < isoline.size(); ++i) {
        EXPECT_NEAR(distanceToPolyline(isoline[i], contour), std::abs(offset), 0.05)
            << "offset " << offset << " point " << i;
        if (i == 0) continue;
        largest_gap = std::max(largest_gap, (isoline[i] - isoline[i - 1]).norm());
        smallest_gap = std::min(smallest_gap, (isoline[i] - isoline[i - 1]).norm());
      }
      EXPECT_LE(largest_gap, 0.25 + 1e-9);
      EXPECT_GT(smallest_gap, 1e-6);  // no repeated points (the fit's parameters would repeat)
    }
  }
}

// An inflated square next to a neighbour keeps `clearance` from it and says so.
TEST(OffsetContourTest, AnObstacleLimitsTheInflatedRegion) {
  const Polyline square = {{0, 0}, {20, 0}, {20, 20}, {0, 20}, {0, 0}};
  const Polyline neighbour = {{30, 0}, {40, 0}, {40, 20}, {30, 20}, {30, 0}};
  bool limited = false;
  const Polyline free = offsetIsolineAvoiding(square, 6.0, {neighbour}, 2.0, &limited);
  EXPECT_FALSE(limited);  // 6 px from the square never comes within 2 px of x = 30
  const Polyline stopped = offsetIsolineAvoiding(square, 9.0, {neighbour}, 2.0, &limited);
  EXPECT_TRUE(limited);
  double closest = 1e9;
  for (const Point2& p : stopped) closest = std::min(closest, distanceToPolyline(p, neighbour));
  EXPECT_NEAR(closest, 2.0, 0.02);
  for (const Point2& p : free) EXPECT_NEAR(distanceToPolyline(p, square), 6.0, 0.02);
}

// A contour given without its closing point is taken as closed, as the region it bounds.
TEST(OffsetContourTest, AnOpenPolylineIsClosed) {
  const Polyline open_square = {{0, 0}, {40, 0}, {40, 40}, {0, 40}};
  const Polyline closed_square = {{0, 0}, {40, 0}, {40, 40}, {0, 40}, {0, 0}};
  const Polyline isoline = offsetIsoline(open_square, -4.0);
  ASSERT_GT(isoline.size(), 100u);
  for (const Point2& p : isoline) EXPECT_NEAR(distanceToPolyline(p, closed_square), 4.0, 0.05);
}

// Repeated points (a degenerate Bezier segment samples one point many times) change nothing,
// nor do corners whose coordinates do not round-trip through a + (b - a): inflated, a square's
// corners are arcs around its vertices, inset they are corners.
TEST(OffsetContourTest, RepeatedPointsAndInexactVerticesChangeNothing) {
  Polyline square, plain;
  for (int i = 0; i < 4; ++i) {
    const double angle = 0.3 + i * M_PI / 2;
    const Point2 corner = Point2(50.123, 50.456) + 28.37 * Point2(std::cos(angle), std::sin(angle));
    plain.push_back(corner);
    for (int k = 0; k < 3; ++k) square.push_back(corner);
  }
  square.push_back(square.front());
  plain.push_back(plain.front());
  for (const Polyline& contour : {plain, square}) {
    for (double offset : {3.0, -3.0}) {
      const Polyline isoline = offsetIsoline(contour, offset);
      ASSERT_GT(isoline.size(), 100u);
      for (const Point2& p : isoline) EXPECT_NEAR(distanceToPolyline(p, plain), 3.0, 0.05);
    }
  }
}

TEST(OffsetContourTest, NonFiniteInputGivesNoIsoline) {
  Polyline circle = circlePolygon(40, true);
  EXPECT_TRUE(offsetIsoline(circle, std::nan("")).empty());
  circle[3].x() = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(offsetIsoline(circle, -2.0).empty());
}

// A dumbbell (a large and a small disc joined by a neck 6 px wide) shrunk by 5 px falls apart:
// the isoline is the large disc's part, every point at the offset from the contour.
TEST(OffsetContourTest, AShrunkRegionThatSplitsKeepsItsLargestPart) {
  Polyline dumbbell;
  const auto arc = [&](const Point2& centre, double radius, double from, double to) {
    for (int i = 0; i <= 200; ++i) {
      const double angle = from + (to - from) * i / 200;
      dumbbell.push_back(centre + radius * Point2(std::cos(angle), std::sin(angle)));
    }
  };
  const double big = std::asin(3.0 / 40.0), small = std::asin(3.0 / 20.0);
  arc({60, 100}, 40, big, 2 * M_PI - big);              // large disc, open to the right
  arc({160, 100}, 20, M_PI + small, 3 * M_PI - small);  // small disc, open to the left
  dumbbell.push_back(dumbbell.front());
  const Polyline isoline = offsetIsoline(dumbbell, -5.0);
  ASSERT_GT(isoline.size(), 100u);
  for (const Point2& p : isoline) {
    EXPECT_LT(p.x(), 100.0);  // nothing of the small disc or the neck
    EXPECT_NEAR(distanceToPolyline(p, dumbbell), 5.0, 0.05);
  }
  EXPECT_NEAR(std::abs(polylineArea(isoline)), M_PI * 35 * 35, 0.01 * M_PI * 35 * 35);
}

// The raster is capped (2048 cells a side): a huge inflation stays cheap and still exact, as the
// points are projected onto the isoline.
TEST(OffsetContourTest, AHugeInflationIsExactOnACappedGrid) {
  expectRadius(offsetIsoline(circlePolygon(40, true), 5000.0), 5040.0, 0.05);
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
