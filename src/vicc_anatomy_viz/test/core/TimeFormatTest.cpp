// ISO 8601 examination times, kept to the microsecond.
#include <gtest/gtest.h>

#include <limits>

#include "vicc_anatomy_viz/time_format.hpp"

namespace vicc_anatomy_viz {
namespace {

constexpr TimestampUs kSecond = kMicrosPerSecond;

TEST(TimeFormatTest, ParsesDatesTimesAndOffsets) {
  EXPECT_EQ(parseTimestamp("1970-01-01"), 0);
  EXPECT_EQ(parseTimestamp("2023-03-06T09:15:00Z"), 1678094100 * kSecond);
  EXPECT_EQ(parseTimestamp("2023-03-06T09:15"), 1678094100 * kSecond);
  EXPECT_EQ(parseTimestamp("2023-03-06T10:15:00+01:00"), 1678094100 * kSecond);
  EXPECT_EQ(parseTimestamp("2023-03-06T09:15:00.250Z"), 1678094100 * kSecond + 250000);
  EXPECT_EQ(parseTimestamp("2024-02-29"), 1709164800 * kSecond);
  EXPECT_EQ(parseTimestamp("2023-03-06T23:15:00+14:00"), 1678094100 * kSecond);
  EXPECT_EQ(parseTimestamp("2023-03-05T21:15:00-12:00"), 1678094100 * kSecond);
}

TEST(TimeFormatTest, SubSecondReadingsDoNotCollide) {
  // Two readings within one second used to be truncated to the same examination time.
  const auto early = parseTimestamp("2023-03-06T09:15:00.1Z");
  const auto late = parseTimestamp("2023-03-06T09:15:00.9Z");
  ASSERT_TRUE(early && late);
  EXPECT_EQ(*late - *early, 800000);
  EXPECT_EQ(parseTimestamp("2023-03-06T09:15:00.000001Z"), 1678094100 * kSecond + 1);
  EXPECT_EQ(parseTimestamp("2023-03-06T09:15:00.123456000Z"), 1678094100 * kSecond + 123456);
  std::string why;
  EXPECT_FALSE(parseTime("2023-03-06T09:15:00.1234567Z", &why));
  EXPECT_NE(why.find("finer than a microsecond"), std::string::npos) << why;
}

TEST(TimeFormatTest, RejectsMalformedAndImpossibleTimes) {
  for (const char* text :
       {"", "2023-3-6", "2023-02-29", "2023-13-01", "2023-03-06T25:00", "2023-03-06T09:15:00+1",
        "06.03.2023", "2023-03-06T09:15:00Zx", "2023-03-06T09:15:00.Z", "2023-03-06T09:15:61Z"}) {
    EXPECT_FALSE(parseTimestamp(text).has_value()) << text;
  }
}

TEST(TimeFormatTest, OffsetsBeyondFourteenHoursAreRejected) {
  std::string why;
  EXPECT_FALSE(parseTime("2023-03-06T09:15:00+14:59", &why));
  EXPECT_NE(why.find("beyond +-14:00"), std::string::npos) << why;
  EXPECT_FALSE(parseTime("2023-03-06T09:15:00-23:00", &why));
  EXPECT_FALSE(parseTime("2023-03-06T09:15:00+05:60", &why));
}

TEST(TimeFormatTest, LeapSecondIsRejectedNotMovedToFiftyNine) {
  std::string why;
  EXPECT_FALSE(parseTime("2016-12-31T23:59:60Z", &why));
  EXPECT_NE(why.find("leap second"), std::string::npos) << why;
}

TEST(TimeFormatTest, TellsWhetherAnOffsetWasGiven) {
  EXPECT_TRUE(parseTime("2023-03-06T09:15:00Z")->has_offset);
  EXPECT_TRUE(parseTime("2023-03-06T09:15:00+02:00")->has_offset);
  EXPECT_FALSE(parseTime("2023-03-06T09:15:00")->has_offset);
  EXPECT_TRUE(parseTime("2023-03-06")->date_only);
}

TEST(TimeFormatTest, PlausibilityRejectsFarFutureAndOldDates) {
  TimePlausibility plausibility;
  plausibility.now = *parseTimestamp("2026-12-01T12:00:00Z");
  EXPECT_EQ(plausibility.problem(*parseTimestamp("2026-12-02T11:00:00Z")), "");
  EXPECT_NE(plausibility.problem(*parseTimestamp("2999-01-01")).find("in the future"),
            std::string::npos);
  EXPECT_NE(plausibility.problem(*parseTimestamp("9999-12-31")), "");
  EXPECT_NE(plausibility.problem(*parseTimestamp("1899-12-31")).find("before 1900"),
            std::string::npos);
  plausibility.max_future_seconds = 0;
  EXPECT_NE(plausibility.problem(*parseTimestamp("2026-12-01T12:00:01Z")), "");
}

TEST(TimeFormatTest, UpperBoundCoversTheGivenDayOrSecond) {
  EXPECT_EQ(parseUpperBound("2023-03-06"), *parseTimestamp("2023-03-06") + 86400 * kSecond - 1);
  EXPECT_EQ(parseUpperBound("2023-03-06T09:15:00Z"), 1678094100 * kSecond + kSecond - 1);
  EXPECT_EQ(parseUpperBound("2023-03-06T09:15:00.5Z"), 1678094100 * kSecond + 500000);
}

TEST(TimeFormatTest, FormatsUtcWithFractionsAndRoundTrips) {
  EXPECT_EQ(formatTimestamp(1678094100 * kSecond), "2023-03-06T09:15:00Z");
  EXPECT_EQ(formatTimestamp(1678094100 * kSecond + 250000), "2023-03-06T09:15:00.25Z");
  EXPECT_EQ(formatTimestamp(1678094100 * kSecond + 1), "2023-03-06T09:15:00.000001Z");
  EXPECT_EQ(formatTimestamp(-kSecond), "1969-12-31T23:59:59Z");
  EXPECT_EQ(formatTimestamp(-1), "1969-12-31T23:59:59.999999Z");
  for (const TimestampUs time :
       {TimestampUs{0}, 1709164800 * kSecond + 4321, TimestampUs{-1}, -2208988800 * kSecond + 7}) {
    EXPECT_EQ(parseTimestamp(formatTimestamp(time)), time) << formatTimestamp(time);
  }
}

// Found by the validator fuzz target: the most negative time overflowed when negated.
TEST(TimeFormatTest, ExtremeTimesFormatWithoutOverflow) {
  const TimestampUs lowest = std::numeric_limits<TimestampUs>::min();
  const TimestampUs highest = std::numeric_limits<TimestampUs>::max();
  EXPECT_EQ(wholeSeconds(lowest), -9223372036855);  // -9223372036854.775808 s, floored
  EXPECT_EQ(microsWithinSecond(lowest), 224192);
  EXPECT_EQ(wholeSeconds(highest), 9223372036854);
  EXPECT_EQ(microsWithinSecond(highest), 775807);
  EXPECT_EQ(wholeSeconds(-1), -1);
  EXPECT_EQ(microsWithinSecond(-1), 999999);
  EXPECT_FALSE(parseTimestamp(formatTimestamp(lowest)).has_value());  // no four-digit year
  EXPECT_FALSE(parseTimestamp(formatTimestamp(highest)).has_value());
}

}  // namespace
}  // namespace vicc_anatomy_viz
