// The panel's timeline: slider positions, "latest", a fixed date kept when the dates change.
#include <gtest/gtest.h>

#include <stdexcept>

#include "vicc_anatomy_viz/panel_logic/timeline_state.hpp"

using vicc_anatomy_viz::panel::TimelineState;

namespace {

const std::vector<std::string> kTwoDates = {"2023-03-06T09:15:00Z", "2023-03-10T08:40:00Z"};

}  // namespace

TEST(TimelineStateTest, LatestSitsOnTheNewestExaminationAndFollowsANewOne) {
  TimelineState timeline;
  EXPECT_TRUE(timeline.followsLatest());
  EXPECT_FALSE(timeline.sliderIndex().has_value());
  EXPECT_EQ(timeline.describe(), "no examinations");
  timeline.setDates(kTwoDates);
  EXPECT_EQ(timeline.sliderIndex(), 1u);
  EXPECT_EQ(timeline.requestedDate(), "");
  EXPECT_EQ(timeline.describe(), "latest: 2023-03-10T08:40:00Z (2 of 2)");
  auto three = kTwoDates;
  three.push_back("2023-06-01T10:00:00Z");
  timeline.setDates(three);
  EXPECT_EQ(timeline.sliderIndex(), 2u);
  EXPECT_EQ(timeline.requestedDate(), "");
}

TEST(TimelineStateTest, SelectingAnIndexFixesThatDateAndKeepsItWhenDatesChange) {
  TimelineState timeline;
  timeline.setDates(kTwoDates);
  ASSERT_TRUE(timeline.selectIndex(0));
  EXPECT_FALSE(timeline.followsLatest());
  EXPECT_EQ(timeline.requestedDate(), "2023-03-06T09:15:00Z");
  EXPECT_EQ(timeline.describe(), "2023-03-06T09:15:00Z (1 of 2)");
  // An earlier examination recorded later: the same examination stays selected, one further on.
  timeline.setDates({"2023-01-02T08:00:00Z", kTwoDates[0], kTwoDates[1]});
  EXPECT_EQ(timeline.sliderIndex(), 1u);
  EXPECT_EQ(timeline.requestedDate(), "2023-03-06T09:15:00Z");
  EXPECT_FALSE(timeline.selectIndex(3));
  EXPECT_EQ(timeline.requestedDate(), "2023-03-06T09:15:00Z");
}

TEST(TimelineStateTest, AFixedDateSitsOnTheExaminationAtOrBeforeIt) {
  TimelineState timeline;
  timeline.setDates(kTwoDates);
  timeline.requestDate("2023-03-08");
  EXPECT_EQ(timeline.sliderIndex(), 0u);
  timeline.requestDate("2023-03-10");  // a day means its end: the examination that morning
  EXPECT_EQ(timeline.sliderIndex(), 1u);
  timeline.requestDate("2023-03-10T08:39:59Z");
  EXPECT_EQ(timeline.sliderIndex(), 0u);
  timeline.requestDate("2023-03-01");
  EXPECT_FALSE(timeline.sliderIndex().has_value());
  EXPECT_EQ(timeline.describe(), "no examination at or before 2023-03-01");
  timeline.requestDate("");
  EXPECT_TRUE(timeline.followsLatest());
}

TEST(TimelineStateTest, RejectsDatesThatAreNotIso8601) {
  TimelineState timeline;
  timeline.setDates(kTwoDates);
  timeline.selectIndex(0);
  EXPECT_THROW(timeline.requestDate("06.03.2023"), std::invalid_argument);
  EXPECT_EQ(timeline.requestedDate(), "2023-03-06T09:15:00Z");  // unchanged
  const auto problems = timeline.setDates({"2023-03-10T08:40:00Z", "yesterday", kTwoDates[0]});
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find("'yesterday'"), std::string::npos);
  ASSERT_EQ(timeline.size(), 2u);
  EXPECT_EQ(timeline.dateAt(0), kTwoDates[0]);  // ordered oldest first
  EXPECT_EQ(timeline.dateAt(1), kTwoDates[1]);
}
