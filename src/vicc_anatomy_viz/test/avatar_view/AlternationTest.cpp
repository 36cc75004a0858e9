#include <gtest/gtest.h>

#include "synthetic_avatar.hpp"
#include "vicc_anatomy_viz/avatar_view/alternation.hpp"

namespace vicc_anatomy_viz::avatar_view {
namespace {

AvatarDrawState alternatingPainAndHypoesthesia() {
  EncodedStatus status =
      testing::statusWith({testing::entry("dermatome_L5", Side::kLeft, "pain"),
                           testing::entry("dermatome_L5", Side::kLeft, "hypo"),
                           testing::entry("extensor_hallucis_longus", Side::kRight, "paresis")});
  status.structures[0].alternation_group = 0;
  status.structures[1].alternation_group = 0;
  status.alternations.resize(1);
  status.alternations[0].entries = {0, 1};
  return buildDrawState(status, testing::syntheticAvatar());
}

TEST(AlternationTest, MembersTakeTurnsEachPeriod) {
  const AlternationCycle cycle(alternatingPainAndHypoesthesia(), 1.5);
  EXPECT_TRUE(cycle.shown(0, 0.0));
  EXPECT_FALSE(cycle.shown(1, 0.0));
  EXPECT_TRUE(cycle.shown(0, 1.49));
  EXPECT_FALSE(cycle.shown(0, 1.51));
  EXPECT_TRUE(cycle.shown(1, 1.51));
  EXPECT_TRUE(cycle.shown(0, 3.01));
  EXPECT_EQ(cycle.step(1.4), 0);
  EXPECT_EQ(cycle.step(1.6), 1);
  // The structure outside the group is always shown.
  for (double t : {0.0, 1.6, 3.2}) EXPECT_TRUE(cycle.shown(2, t));
  EXPECT_FALSE(cycle.shown(7, 0.0));
}

TEST(AlternationTest, TheAlternationsViewOrderDecidesWhoIsShownFirst) {
  EncodedStatus status = testing::statusWith({testing::entry("dermatome_L5", Side::kLeft, "hypo"),
                                              testing::entry("dermatome_L5", Side::kLeft, "pain")});
  status.structures[0].alternation_group = 0;
  status.structures[1].alternation_group = 0;
  status.alternations.resize(1);
  status.alternations[0].entries = {1, 0};  // pain first, although listed second
  const AlternationCycle cycle(buildDrawState(status, testing::syntheticAvatar()), 1.0);
  EXPECT_TRUE(cycle.shown(1, 0.5));
  EXPECT_FALSE(cycle.shown(0, 0.5));
  EXPECT_TRUE(cycle.shown(0, 1.5));
}

TEST(AlternationTest, NoPeriodShowsTheFirstMember) {
  for (double period : {0.0, -1.0, std::numeric_limits<double>::infinity()}) {
    const AlternationCycle cycle(alternatingPainAndHypoesthesia(), period);
    EXPECT_TRUE(cycle.shown(0, 10.0)) << period;
    EXPECT_FALSE(cycle.shown(1, 10.0)) << period;
  }
}

TEST(AlternationTest, AGroupLeftWithOneDrawnMemberDoesNotAlternate) {
  EncodedStatus status = testing::statusWith(
      {testing::entry("dermatome_L5", Side::kLeft, "pain"),
       testing::entry("dermatome_L5", Side::kLeft, "hypo", {std::nanf(""), 0.f, 0.f, 1.f})});
  status.structures[0].alternation_group = 0;
  status.structures[1].alternation_group = 0;
  status.alternations.resize(1);
  status.alternations[0].entries = {0, 1};
  const AlternationCycle cycle(buildDrawState(status, testing::syntheticAvatar()), 1.0);
  EXPECT_TRUE(cycle.groups().empty());
  EXPECT_TRUE(cycle.shown(0, 1.5));
}

}  // namespace
}  // namespace vicc_anatomy_viz::avatar_view
