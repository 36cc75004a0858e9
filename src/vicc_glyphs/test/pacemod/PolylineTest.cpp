// Polyline helpers of PACEMOD: the bucketed distance and nearest-point queries against the plain
// distance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include "vicc_glyphs/pacemod/polyline.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

TEST(PolylineTest, BucketedDistanceEqualsTheExhaustiveOne) {
  Polyline star;  // a closed star with spikes, 400 vertices
  for (int i = 0; i <= 400; ++i) {
    const double angle = 2 * M_PI * i / 400;
    const double radius = 60 + 25 * std::sin(9 * angle);
    star.push_back(Point2(200 + radius * std::cos(angle), 150 + radius * std::sin(angle)));
  }
  const PolylineDistance distance(star, 4.0);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-100, 500);
  for (int k = 0; k < 2000; ++k) {
    const Point2 p(coordinate(random), coordinate(random));
    EXPECT_NEAR(distance(p), distanceToPolyline(p, star), 1e-9) << p.transpose();
    int segment = -1;
    const Point2 nearest = distance.nearest(p, &segment);
    EXPECT_NEAR((nearest - p).norm(), distanceToPolyline(p, star), 1e-9) << p.transpose();
    ASSERT_GE(segment, 0);  // and the point lies on the segment named
    EXPECT_NEAR(distanceToPolyline(nearest, {star[segment], star[segment + 1]}), 0.0, 1e-9);
  }
  EXPECT_NEAR(distance(star[17]), 0.0, 1e-12);
  const Polyline empty;
  EXPECT_TRUE(std::isinf(PolylineDistance(empty)(Point2(1, 2))));
  EXPECT_FALSE(PolylineDistance(empty).nearest(Point2(1, 2)).allFinite());
  EXPECT_FALSE(distance.nearest(Point2(NAN, 2)).allFinite());
}

// The centre of a square is as near to all four sides: the lowest segment index is named,
// whatever the grid and so the order its cells are visited in.
TEST(PolylineTest, EqualDistancesNameTheLowestSegment) {
  const Polyline square = {{10, 10}, {30, 10}, {30, 30}, {10, 30}, {10, 10}};
  for (const double cell : {0.5, 3.0, 7.0, 40.0}) {
    int segment = -1;
    const Point2 nearest = PolylineDistance(square, cell).nearest(Point2(20, 20), &segment);
    EXPECT_EQ(segment, 0) << cell;
    EXPECT_NEAR((nearest - Point2(20, 10)).norm(), 0.0, 1e-12) << cell;
  }
}

// A cell far too small for the polyline's extent is coarsened (the grid stays within 4 M cells),
// a query far outside the grid is answered by trying every segment, a bad cell is refused.
TEST(PolylineTest, BucketedDistanceCopesWithTinyCellsAndFarQueries) {
  const Polyline line = {{0, 0}, {300, 40}, {120, 400}, {-50, 90}};
  const PolylineDistance tiny(line, 1e-6);
  const PolylineDistance coarse(line, 4.0);
  for (const Point2& p :
       {Point2(10, 10), Point2(200, 300), Point2(1e17, -3e16), Point2(-5e15, 2)}) {
    EXPECT_NEAR(tiny(p), distanceToPolyline(p, line), 1e-9 * (1 + p.norm())) << p.transpose();
    EXPECT_NEAR(coarse(p), distanceToPolyline(p, line), 1e-9 * (1 + p.norm())) << p.transpose();
  }
  for (double cell : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
    EXPECT_THROW(PolylineDistance(line, cell), std::invalid_argument) << cell;
  }
}

// Several polylines at once (the skeleton guard's curves): the nearest point over all of them,
// and with a radius only a point nearer than it.
TEST(PolylineTest, NearestOfSeveralPolylinesEqualsTheExhaustiveOneWithinARadius) {
  std::vector<Polyline> lines;
  for (int ring = 0; ring < 3; ++ring) {  // three wavy rings inside each other, one open
    Polyline line;
    for (int i = 0; i <= 300 - 40 * ring; ++i) {
      const double angle = 2 * M_PI * i / 300;
      const double radius = 40 + 25 * ring + 4 * std::sin((7 + ring) * angle);
      line.push_back(Point2(150 + radius * std::cos(angle), 140 + radius * std::sin(angle)));
    }
    lines.push_back(line);
  }
  const PolylineSetDistance set({&lines[0], &lines[1], &lines[2]}, 8.0);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> coordinate(-50, 350), radius(0.5, 30.0);
  for (int k = 0; k < 2000; ++k) {
    const Point2 p(coordinate(random), coordinate(random));
    double exact = std::numeric_limits<double>::infinity();
    for (const Polyline& line : lines) exact = std::min(exact, distanceToPolyline(p, line));
    const PolylineSetDistance::Segment nearest = set.nearestSegment(p);
    ASSERT_GE(nearest.line, 0) << p.transpose();
    const Point2 point = set.nearestOn(nearest, p);
    EXPECT_NEAR((point - p).norm(), exact, 1e-9) << p.transpose();
    const Polyline& line = lines[nearest.line];  // the point lies on the segment named
    EXPECT_NEAR(distanceToPolyline(point, {line[nearest.segment], line[nearest.segment + 1]}), 0.0,
                1e-9);
    const double r = radius(random);
    const PolylineSetDistance::Segment within = set.nearestSegment(p, r);
    EXPECT_EQ(within.line >= 0, exact < r) << p.transpose() << " radius " << r;
    if (within.line >= 0) {
      EXPECT_NEAR((set.nearestOn(within, p) - p).norm(), exact, 1e-9);
    }
  }
  EXPECT_LT(set.nearestSegment(Point2(NAN, 3)).line, 0);
  EXPECT_LT(set.nearestSegment(lines[1][5], 0.0).line, 0);  // nothing is nearer than 0
  EXPECT_GE(set.nearestSegment(lines[1][5], 1e-9).line, 0);
  EXPECT_TRUE(PolylineSetDistance({}).empty());
}

// Arc lengths on a closed contour of length 10: the shorter way round, across 0 = L as well.
TEST(PolylineTest, CyclicOffsetTakesTheShorterWayRound) {
  EXPECT_DOUBLE_EQ(cyclicOffset(2.0, 3.5, 10.0), 1.5);
  EXPECT_DOUBLE_EQ(cyclicOffset(3.5, 2.0, 10.0), -1.5);
  EXPECT_DOUBLE_EQ(cyclicOffset(9.5, 0.5, 10.0), 1.0);   // forwards past the closing point
  EXPECT_DOUBLE_EQ(cyclicOffset(0.5, 9.5, 10.0), -1.0);  // backwards past it
  EXPECT_DOUBLE_EQ(cyclicOffset(1.0, 5.0, 10.0), 4.0);
  EXPECT_DOUBLE_EQ(cyclicOffset(1.0, 7.0, 10.0), -4.0);
  EXPECT_DOUBLE_EQ(cyclicDistance(9.5, 0.5, 10.0), 1.0);
  EXPECT_DOUBLE_EQ(cyclicDistance(0.0, 10.0, 10.0), 0.0);  // the closing point twice
  EXPECT_DOUBLE_EQ(cyclicDistance(2.0, 7.0, 10.0), 5.0);
}

}  // namespace
}  // namespace pacemod
}  // namespace vicc_glyphs
