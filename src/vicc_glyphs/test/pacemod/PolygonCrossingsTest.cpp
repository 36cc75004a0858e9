#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <tuple>

#include "vicc_glyphs/pacemod/polygon_crossings.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

using PairKey = std::tuple<int, int, int, int>;

PairKey key(SegmentRef p, SegmentRef q) {
  if (std::tie(q.line, q.segment) < std::tie(p.line, p.segment)) std::swap(p, q);
  return {p.line, p.segment, q.line, q.segment};
}

double cross(const Point2& a, const Point2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Every pair of segments, checked directly (the definition findCrossings must match).
std::set<PairKey> exhaustiveCrossings(const std::vector<Polyline>& lines) {
  std::set<PairKey> found;
  for (int l = 0; l < static_cast<int>(lines.size()); ++l) {
    const int segments = static_cast<int>(lines[l].size()) - 1;
    const bool closed = (lines[l].front() - lines[l].back()).norm() < 1e-9;
    for (int m = l; m < static_cast<int>(lines.size()); ++m) {
      for (int i = 0; i < segments; ++i) {
        for (int j = (m == l ? i + 1 : 0); j + 1 < static_cast<int>(lines[m].size()); ++j) {
          if (m == l && (j - i <= 1 || (closed && j - i == segments - 1))) continue;
          const Point2 &a = lines[l][i], &b = lines[l][i + 1];
          const Point2 &c = lines[m][j], &d = lines[m][j + 1];
          if (cross(b - a, c - a) * cross(b - a, d - a) < 0.0 &&
              cross(d - c, a - c) * cross(d - c, b - c) < 0.0) {
            found.insert({l, i, m, j});
          }
        }
      }
    }
  }
  return found;
}

// Random closed zigzags: many crossings within and between lines, some exactly on cell
// borders (integer coordinates with the default 8 px cell).
TEST(PolygonCrossingsTest, FindsExactlyTheCrossingsOfTheExhaustiveCheckOnce) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(0.0, 64.0);
  for (int round = 0; round < 20; ++round) {
    std::vector<Polyline> lines(3);
    for (Polyline& line : lines) {
      for (int k = 0; k < 25; ++k) {
        const double x = coordinate(random), y = coordinate(random);
        line.push_back(round % 2 ? Point2(std::round(x), std::round(y)) : Point2(x, y));
      }
      line.push_back(line.front());
    }
    const std::vector<Crossing> crossings = findCrossings(lines);
    std::set<PairKey> reported;
    for (const Crossing& c : crossings) {
      EXPECT_TRUE(reported.insert(key(c.a, c.b)).second) << "reported twice";
    }
    EXPECT_EQ(reported, exhaustiveCrossings(lines)) << "round " << round;
    EXPECT_GT(reported.size(), 50u);
    EXPECT_EQ(findCrossings(lines, 3.0).size(), crossings.size());
  }
}

// Finely sampled curves with loops (trochoids: a point on a wheel rolling around a circle), as
// the flattened waves are: several segments per grid cell, crossings within and between lines
// and near cell borders (the random zigzags above have segments longer than a cell).
TEST(PolygonCrossingsTest, FinelySampledLoopsGiveTheExhaustiveCrossings) {
  const std::vector<std::tuple<double, double, int, Point2>> loops{
      {20.0, 6.0, 9, {32.0, 32.0}}, {18.0, 5.0, 11, {40.0, 30.0}}, {12.0, 8.0, 7, {30.0, 42.0}}};
  for (const double step : {0.3, 0.9}) {
    std::vector<Polyline> lines;
    for (const auto& [radius, wheel, turns, centre] : loops) {
      Polyline line;
      const int samples = static_cast<int>(2.0 * M_PI * (radius + wheel) * turns / 4.0 / step);
      for (int k = 0; k < samples; ++k) {
        const double t = 2.0 * M_PI * k / samples;
        line.push_back(centre + radius * Point2(std::cos(t), std::sin(t)) +
                       wheel * Point2(std::cos(turns * t), std::sin(turns * t)));
      }
      line.push_back(line.front());
      lines.push_back(line);
    }
    for (const double cell : {2.0, 8.0}) {
      const std::vector<Crossing> crossings = findCrossings(lines, cell);
      std::set<PairKey> reported;
      for (const Crossing& c : crossings) reported.insert(key(c.a, c.b));
      EXPECT_EQ(reported.size(), crossings.size()) << "reported twice";
      const std::set<PairKey> expected = exhaustiveCrossings(lines);
      EXPECT_EQ(reported, expected) << "step " << step << ", cell " << cell;
      EXPECT_GT(expected.size(), 40u);
    }
  }
}

// One finder for a sequence of searches (as the repair rounds use it): larger and smaller sets,
// other extents, none at all; each time exactly the exhaustive check's crossings.
TEST(PolygonCrossingsTest, AReusedFinderKeepsNothingOfTheSearchBefore) {
  std::mt19937 random(11);
  CrossingFinder finder;
  for (const auto& [line_count, extent] : std::vector<std::pair<int, double>>{
           {4, 64.0}, {1, 16.0}, {0, 0.0}, {3, 200.0}, {2, 8.0}, {4, 64.0}}) {
    std::uniform_real_distribution<double> coordinate(0.0, extent);
    std::vector<Polyline> lines(line_count);
    for (Polyline& line : lines) {
      for (int k = 0; k < 20; ++k) line.push_back({coordinate(random), coordinate(random)});
      line.push_back(line.front());
    }
    const std::vector<Crossing> crossings = finder.find(lines, 2.0);
    std::set<PairKey> reported;
    for (const Crossing& c : crossings) reported.insert(key(c.a, c.b));
    EXPECT_EQ(reported.size(), crossings.size());
    EXPECT_EQ(reported, exhaustiveCrossings(lines)) << line_count << " lines over " << extent;
  }
}

// The search pairs runs of segments along which x does not turn back. Random walks on an
// integer lattice make the cases such runs must get right: vertical steps (x stays) inside and
// between runs, repeated points, collinear overlaps, runs longer than a cell and back-and-forth
// steps; a non-finite point splits a line (its two segments count nowhere).
TEST(PolygonCrossingsTest, LatticeWalksGiveTheExhaustiveCrossings) {
  std::mt19937 random(23);
  std::uniform_int_distribution<int> step(-2, 2), length(1, 6), lines_in_set(1, 4);
  int total = 0;
  for (int round = 0; round < 40; ++round) {
    std::vector<Polyline> lines(lines_in_set(random));
    for (Polyline& line : lines) {
      Point2 at(step(random) * 5.0, step(random) * 5.0);
      line.push_back(at);
      for (int k = 0; k < 60; ++k) {
        // Mostly axis-parallel runs of several unit steps, sometimes a diagonal one.
        const Point2 direction(step(random), k % 3 == 0 ? step(random) : 0);
        for (int n = length(random); n > 0; --n) line.push_back(at += direction);
        if (k % 2) line.push_back(at += Point2(0, step(random)));
      }
      if (round % 4 == 1) line.push_back(line.front());
      if (round % 4 == 2) line[line.size() / 2] = Point2(std::nan(""), 0.0);
    }
    for (const double cell : {1.0, 8.0}) {
      const std::vector<Crossing> crossings = findCrossings(lines, cell);
      std::set<PairKey> reported;
      for (const Crossing& c : crossings) reported.insert(key(c.a, c.b));
      EXPECT_EQ(reported.size(), crossings.size()) << "reported twice, round " << round;
      EXPECT_EQ(reported, exhaustiveCrossings(lines)) << "round " << round << ", cell " << cell;
      total += static_cast<int>(reported.size());
    }
  }
  EXPECT_GT(total, 500);
}

TEST(PolygonCrossingsTest, NeighboursAndTouchingEndsDoNotCount) {
  const Polyline square{{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}};
  EXPECT_TRUE(findCrossings({square}).empty());
  const Polyline bow{{0, 0}, {10, 10}, {10, 0}, {0, 10}, {0, 0}};
  ASSERT_EQ(findCrossings({bow}).size(), 1u);
  EXPECT_EQ(findCrossings({bow})[0].a.segment, 0);
  EXPECT_EQ(findCrossings({bow})[0].b.segment, 2);
}

// A far-flung polyline (e.g. a huge wave amplitude) coarsens the grid instead of allocating
// or visiting ~10^13 cells.
TEST(PolygonCrossingsTest, TheCrossingPointIsWhereTheTwoSegmentsMeet) {
  const std::vector<Polyline> lines{{{0, 0}, {10, 0}, {10, 10}}, {{2, -1}, {4, 3}}};
  const std::vector<Crossing> crossings = findCrossings(lines);
  ASSERT_EQ(crossings.size(), 1u);
  const Point2 point = crossingPoint(lines, crossings.front());
  EXPECT_NEAR(point.x(), 2.5, 1e-12);  // (2, -1) + 0.25 (2, 4)
  EXPECT_NEAR(point.y(), 0.0, 1e-12);
}

// The search's boxes are floats: rounded to the nearest, the nearly vertical segment's box
// (x from 2 - 1e-9 to 2 + 1e-9) would become x = 2 exactly and sit in the 2 px cells right of
// x = 2 only, while the two segments cross at x = 2 - 9e-10, in the cell left of it.
TEST(PolygonCrossingsTest, BoxesRoundedOutwardKeepACrossingNextToACellBorder) {
  const std::vector<Polyline> lines{{{2.0 - 1e-9, -1.0}, {2.0 + 1e-9, 1.0}},
                                    {{0.0, -0.9}, {3.0, -0.9}}};
  const std::vector<Crossing> crossings = findCrossings(lines, 2.0);
  ASSERT_EQ(crossings.size(), 1u);
  EXPECT_LT(crossingPoint(lines, crossings.front()).x(), 2.0);
}

TEST(PolygonCrossingsTest, HugeExtentsCoarsenTheGrid) {
  const Polyline far{{0, 0}, {1e7, 1e7}, {1e7, 0}, {0, 1e7}, {0, 0}};
  const std::vector<Crossing> crossings = findCrossings({far}, 0.5);
  ASSERT_EQ(crossings.size(), 1u);
  EXPECT_EQ(crossings[0].b.segment, 2);
  EXPECT_THROW(findCrossings({far}, 0.0), std::invalid_argument);
  EXPECT_THROW(findCrossings({{{-1e308, 0}, {1e308, 1}}}), std::invalid_argument);
}

}  // namespace
}  // namespace pacemod
}  // namespace vicc_glyphs
