#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "vicc_glyphs/pacemod/original_splice.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

using bspline::BSplineCurve;

using Runs = std::vector<std::pair<double, double>>;

Runs runs(const std::vector<ArcInterval>& intervals) {
  Runs out;
  for (const ArcInterval& interval : intervals) out.emplace_back(interval.begin, interval.end);
  return out;
}

TEST(OriginalSpliceTest, FlatRunsAreConsecutiveZeroTranslationsWithMetEnds) {
  const std::vector<double> parameters{0, 1, 2, 3, 4, 5, 6};
  const std::vector<bool> met(7, false);
  EXPECT_EQ(runs(flatRuns(parameters, {1, 0, 0, 0, 1, 0, 1}, met)), (Runs{{1, 3}}));
  EXPECT_EQ(runs(flatRuns(parameters, {0, 0, 1, 0, 1, 0, 0}, met)), (Runs{{0, 1}, {5, 6}}));
  EXPECT_TRUE(flatRuns(parameters, {1, 0, 1, 0, 1, 0, 1}, met).empty());  // single zeros
  std::vector<bool> unmet = met;
  unmet[3] = true;  // an end the curve does not meet (swallowed): the run stops before it
  EXPECT_EQ(runs(flatRuns(parameters, {1, 0, 0, 0, 1, 0, 1}, unmet)), (Runs{{1, 2}}));
  unmet[3] = false;
  unmet[1] = true;
  EXPECT_EQ(runs(flatRuns(parameters, {1, 0, 0, 0, 1, 0, 1}, unmet)), (Runs{{2, 3}}));
  // Parameters that do not increase (a knot point moved onto a corner behind it) end a run.
  EXPECT_EQ(runs(flatRuns({0, 1, 2, 1.5, 4}, {1, 0, 0, 0, 1}, std::vector<bool>(5, false))),
            (Runs{{1, 2}}));
  // A run that would start before the previous one ends is left out (spliceOriginal needs
  // increasing, disjoint runs).
  EXPECT_EQ(runs(flatRuns({0, 1, 2, 1.5, 1.8, 4}, {1, 0, 0, 0, 0, 1}, std::vector<bool>(6, false))),
            (Runs{{1, 2}}));
  EXPECT_THROW(flatRuns(parameters, {0, 0}, met), std::invalid_argument);
}

// A straight original from (0, 0) to (30, 0), arc length = x; the "wave" meets it at 0, 12, 18
// and 30 and leaves it between (up, up by less, down).
TEST(OriginalSpliceTest, TheRunIsTheOriginalAndTheRestTheWave) {
  const BSplineCurve original(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0}, {10, 0}, {20, 0}, {30, 0}});
  const bspline::ArcLengthTable table(original, 256);
  const BSplineCurve wave(
      3, {0, 0, 0, 0, 12, 12, 12, 18, 18, 18, 30, 30, 30, 30},
      {{0, 0}, {4, 5}, {8, 5}, {12, 0}, {14, 2}, {16, 2}, {18, 0}, {22, -5}, {26, -5}, {30, 0}});
  const BSplineCurve spliced = spliceOriginal(wave, original, table, {{12, 18}});
  EXPECT_DOUBLE_EQ(spliced.domainBegin(), 0.0);
  EXPECT_DOUBLE_EQ(spliced.domainEnd(), 30.0);
  for (double u : {12.0, 13.5, 15.0, 17.9, 18.0}) {
    EXPECT_NEAR(spliced.pointAt(u).x(), u, 1e-9) << u;
    EXPECT_NEAR(spliced.pointAt(u).y(), 0.0, 1e-12) << u;
  }
  for (double u : {0.0, 3.0, 7.5, 11.0, 19.0, 26.0, 30.0}) {
    EXPECT_NEAR((spliced.pointAt(u) - wave.pointAt(u)).norm(), 0.0, 1e-9) << u;
  }
  EXPECT_EQ(spliced.multiplicity(12.0), 3);
  EXPECT_EQ(spliced.multiplicity(18.0), 3);
  // A run shorter than the snapping tolerance leaves the wave as it is.
  const BSplineCurve unchanged = spliceOriginal(wave, original, table, {{12, 12 + 1e-12}});
  EXPECT_EQ(unchanged.knots(), wave.knots());
  EXPECT_THROW(spliceOriginal(wave, original, table, {{18, 12}}), std::invalid_argument);
  EXPECT_THROW(spliceOriginal(wave, original, table, {{10, 20}, {15, 25}}), std::invalid_argument);
  EXPECT_THROW(spliceOriginal(wave, original, table, {{10, 40}}), std::invalid_argument);
}

// A wave of 240 pieces over a straight original from (0, 0) to (240, 0), flat (on the
// original) over 40 runs: the splice cuts it at 80 places in one pass.
TEST(OriginalSpliceTest, ManyRunsOnALongWaveEachBecomeTheOriginal) {
  const BSplineCurve original(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0}, {80, 0}, {160, 0}, {240, 0}});
  const bspline::ArcLengthTable table(original, 4096);
  std::vector<double> knots(4, 0.0);
  std::vector<Point2> points{{0, 0}};
  for (int k = 1; k <= 240; ++k) {  // a C0 tooth of height 1 per unit of length
    const double x0 = k - 1;
    points.insert(points.end(), {{x0 + 1.0 / 3, 1}, {x0 + 2.0 / 3, 1}, {x0 + 1, 0}});
    knots.insert(knots.end(), 3, static_cast<double>(k));
  }
  knots.back() = 240.0;
  knots.push_back(240.0);
  const BSplineCurve wave(3, knots, points);
  std::vector<ArcInterval> runs;
  for (int r = 0; r < 40; ++r) runs.push_back({6.0 * r + 1.25, 6.0 * r + 3.75});
  const BSplineCurve spliced = spliceOriginal(wave, original, table, runs);
  for (const ArcInterval& run : runs) {
    for (double t : {0.0, 0.3, 0.5, 1.0}) {
      const double u = run.begin + t * (run.end - run.begin);
      EXPECT_NEAR(spliced.pointAt(u).y(), 0.0, 1e-9) << u;
      EXPECT_NEAR(spliced.pointAt(u).x(), u, 1e-6) << u;
    }
    EXPECT_EQ(spliced.multiplicity(run.begin), 3) << run.begin;
    EXPECT_EQ(spliced.multiplicity(run.end), 3) << run.end;
  }
  for (int r = 0; r < 40; ++r) {  // between the runs: the wave's teeth
    for (double u : {6.0 * r + 0.5, 6.0 * r + 4.5, 6.0 * r + 5.5}) {
      EXPECT_NEAR((spliced.pointAt(u) - wave.pointAt(u)).norm(), 0.0, 1e-9) << u;
    }
  }
}

}  // namespace
}  // namespace pacemod
}  // namespace vicc_glyphs
