#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "vicc_glyphs/dci/flattening.hpp"
#include "vicc_glyphs/pacemod/offset_contour.hpp"
#include "vicc_glyphs/pacemod/polygon_crossings.hpp"

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

// The boundary of two overlapping discs (radius 20, centres 30 px apart), clockwise on screen,
// points about 0.25 px apart: two concave corners where the circles meet, turning by 97 deg.
Polyline twoDiscs() {
  const Point2 left(40, 50), right(70, 50);
  const double half = std::acos(15.0 / 20.0);  // the meeting points' angle from the x axis
  Polyline line;
  const int steps = 400;
  for (int i = 0; i <= steps; ++i) {  // the left disc's arc, from the lower to the upper point
    const double a = half + (2 * M_PI - 2 * half) * i / steps;
    line.emplace_back(left.x() + 20 * std::cos(a), left.y() + 20 * std::sin(a));
  }
  for (int i = 1; i < steps; ++i) {  // the right disc's arc back
    const double a = M_PI + half + (2 * M_PI - 2 * half) * i / steps;
    line.emplace_back(right.x() + 20 * std::cos(a), right.y() + 20 * std::sin(a));
  }
  line.push_back(line.front());
  return line;
}

double distanceToCurve(const Point2& point, const DiffusionCurve& curve) {
  return distanceToPolyline(point, sampleCurve(curve, 64));
}

// A smooth fit rounds a concave corner off by knot spans (and a cusp into a loop); the chain
// keeps a corner through it and lies on the line elsewhere.
TEST(OffsetContourTest, ClosedBezierFitKeepsSharpCorners) {
  const Polyline line = twoDiscs();
  DiffusionCurve curve;
  curve.control_points = closedBezierFit(line);
  const double y = std::sqrt(20.0 * 20.0 - 15.0 * 15.0);
  for (const Point2& corner : {Point2(55, 50 - y), Point2(55, 50 + y)}) {
    EXPECT_LT(distanceToCurve(corner, curve), 0.05) << corner.transpose();
  }
  for (std::size_t i = 0; i < line.size(); i += 7) {
    EXPECT_LT(distanceToCurve(line[i], curve), 0.05) << line[i].transpose();
  }
  EXPECT_TRUE(findCrossings({flattenCurve(curve)}).empty());
}

Polyline square(double side) {
  Polyline line;
  for (int i = 0; i < 4 * 40; ++i) {  // 40 points per side, clockwise on screen from (0, 0)
    const double t = side * (i % 40) / 40.0;
    const Point2 corner[4] = {{0, 0}, {side, 0}, {side, side}, {0, side}};
    const Point2 along[4] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    line.push_back(corner[i / 40] + t * along[i / 40]);
  }
  line.push_back(line.front());
  return line;
}

// Inserts after point `at` of a closed line a spike into the square (+y), `length` px long,
// `width` px wide at its base: a triangle, or with `flat_top` a finger of that width throughout.
Polyline withSpike(Polyline line, std::size_t at, double length, double width, bool flat_top) {
  const Point2 base = line[at];
  Polyline spike;
  const double narrowing = flat_top ? 0.0 : 0.5 * width;
  for (int k = 1; k <= 8; ++k) spike.push_back(base + Point2(narrowing * k / 8, length * k / 8));
  for (int k = flat_top ? 8 : 7; k >= 0; --k) {
    spike.push_back(base + Point2(width - narrowing * k / 8, length * k / 8));
  }
  line.insert(line.begin() + at + 1, spike.begin(), spike.end());
  return line;
}

TEST(OffsetContourTest, HairsAreCutAndFingersKept) {
  const Polyline plain = square(40);  // point 10 is (10, 0), the next (11, 0)
  const Polyline hair = withoutHairs(withSpike(plain, 10, 10.0, 0.05, false));
  EXPECT_EQ(hair.size(), plain.size() + 1);  // the spike's last point, 0.05 px from its base
  for (const Point2& p : hair) {
    EXPECT_FALSE(p.x() > 0.5 && p.x() < 39.5 && p.y() > 0.5 && p.y() < 39.5) << p.transpose();
  }
  // A finger 1 px wide encloses area: it is part of the region.
  const Polyline finger = withSpike(plain, 10, 10.0, 1.0, true);
  EXPECT_EQ(withoutHairs(finger).size(), finger.size());
  EXPECT_EQ(withoutHairs(plain).size(), plain.size());
}

TEST(OffsetContourTest, SmallLoopsAreCutAtTheirCrossing) {
  Polyline line = square(40);
  // A loop of about 0.6 px after point 10: over to the right, down, back left across the side.
  const Point2 at = line[10];
  line.insert(line.begin() + 11, {at + Point2(0.3, 0), at + Point2(0.3, 0.2), at + Point2(0.1, 0.2),
                                  at + Point2(0.15, -0.1), at + Point2(0.4, -0.1)});
  ASSERT_FALSE(findCrossings({line}).empty());
  const Polyline cut = withoutSmallLoops(line);
  EXPECT_TRUE(findCrossings({cut}).empty());
  EXPECT_LT(cut.size(), line.size());
  EXPECT_LT((cut.front() - cut.back()).norm(), 1e-12);
}

}  // namespace
}  // namespace pacemod
}  // namespace vicc_glyphs
