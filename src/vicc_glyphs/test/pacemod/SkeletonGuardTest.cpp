#include <gtest/gtest.h>

#include <cmath>

#include "vicc_glyphs/pacemod/skeleton_guard.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

TEST(SkeletonGuardTest, SkeletonAmplitudeIsTheLegOfTheIsoscelesTriangle) {
  const Point2 k(0, 0), n(0, 1);
  EXPECT_DOUBLE_EQ(skeletonAmplitude(k, n, {0, 10}), 5.0);    // straight ahead: half way
  EXPECT_DOUBLE_EQ(skeletonAmplitude(k, n, {3, 4}), 3.125);   // 0.5 * 25 / 4
  EXPECT_DOUBLE_EQ(skeletonAmplitude(k, n, {-6, 8}), 6.25);   // 0.5 * 100 / 8
  EXPECT_TRUE(std::isinf(skeletonAmplitude(k, n, {5, -1})));  // behind k
  EXPECT_TRUE(std::isinf(skeletonAmplitude(k, n, {5, 0})));   // beside k
}

// Two parallel lines 11 px apart plus a single curve point p1 = (53, 26) in between.
class GuardFixture : public ::testing::Test {
 protected:
  GuardFixture()
      : field_({{{0, 20}, {100, 20}}, {{0, 31}, {100, 31}}, {{53, 26}, {53, 26}}}, 100, 50, 4.0),
        guard_(field_, 0.5) {}
  NearestCurvePoint field_;
  SkeletonGuard guard_;
};

TEST_F(GuardFixture, ShortTranslationsStayUntouched) {
  const GuardResult result = guard_.limit({40, 20}, {0, 1}, 4.0);
  EXPECT_DOUBLE_EQ(result.amplitude, 4.0);
  EXPECT_FALSE(result.reduced);
  EXPECT_EQ(result.steps, 0);
}

TEST_F(GuardFixture, ATranslationPastTheSkeletonStopsEpsilonBeforeIt) {
  // Far from p1: the other line at distance 11 gives a' = 0.5 * 121 / 11 = 5.5, minus 0.5.
  const GuardResult result = guard_.limit({20, 20}, {0, 1}, 9.0);
  EXPECT_TRUE(result.reduced);
  EXPECT_EQ(result.steps, 1);
  EXPECT_NEAR(result.amplitude, 5.0, 0.02);
}

TEST_F(GuardFixture, TheTestIsRepeatedForTheNextCloserPoint) {
  // k = (50, 20): first the line (a = 5.5 - 0.5 = 5), then from (50, 25) p1 = (53, 26) is
  // closer than k: a' = 0.5 * (9 + 36) / 6 = 3.75, minus 0.5 = 3.25; then k is nearest.
  const GuardResult result = guard_.limit({50, 20}, {0, 1}, 20.0);
  EXPECT_TRUE(result.reduced);
  EXPECT_EQ(result.steps, 2);
  EXPECT_NEAR(result.amplitude, 3.25, 0.02);
}

TEST_F(GuardFixture, OutwardTranslationsAwayFromOtherCurvesAreFree) {
  const GuardResult result = guard_.limit({50, 20}, {0, -1}, 15.0);
  EXPECT_FALSE(result.reduced);
  EXPECT_DOUBLE_EQ(result.amplitude, 15.0);
}

// A reduction that leaves less than a tenth of a pixel leaves nothing: a' = 5.5, epsilon 5.45.
TEST_F(GuardFixture, ReductionsBelowATenthOfAPixelLeaveNothing) {
  const SkeletonGuard wide(field_, 5.45);
  const GuardResult result = wide.limit({20, 20}, {0, 1}, 9.0);
  EXPECT_TRUE(result.reduced);
  EXPECT_EQ(result.amplitude, 0.0);
  const SkeletonGuard narrower(field_, 5.3);  // 0.2 px stay
  EXPECT_NEAR(narrower.limit({20, 20}, {0, 1}, 9.0).amplitude, 0.2, 0.02);
}

// On a field of one grid pixel per pixel (lines through pixel centres, 11 px apart): another
// curve point closer than the amplitude by less than that pixel but by more than kGuardSlack of
// it still limits the amplitude (a whole pixel of slack let 0.8 mm lobes end 12 % short of
// their amplitude beside convex corners).
TEST(SkeletonGuardTest, TheSlackIsAFractionOfTheAmplitudeBelowAGridPixel) {
  const NearestCurvePoint field({{{0, 20.5}, {100, 20.5}}, {{0, 31.5}, {100, 31.5}}}, 100, 50, 1.0);
  const SkeletonGuard guard(field, 0.5);
  ASSERT_DOUBLE_EQ(field.gridPixel(), 1.0);
  // (20, 26.4) is 5.1 from the other line: 0.8 px nearer (over 5 % of 5.9): 5.5 - 0.5.
  const GuardResult limited = guard.limit({20, 20.5}, {0, 1}, 5.9);
  EXPECT_TRUE(limited.reduced);
  EXPECT_NEAR(limited.amplitude, 5.0, 0.05);
  // (20, 26.1) is 5.4 from it: 0.2 px nearer, under 5 % of 5.6.
  const GuardResult kept = guard.limit({20, 20.5}, {0, 1}, 5.6);
  EXPECT_FALSE(kept.reduced);
  EXPECT_DOUBLE_EQ(kept.amplitude, 5.6);
}

}  // namespace
}  // namespace pacemod
}  // namespace vicc_glyphs
