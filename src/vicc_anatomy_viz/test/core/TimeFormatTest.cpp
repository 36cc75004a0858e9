// ISO 8601 examination times.
#include <gtest/gtest.h>

#include "vicc_anatomy_viz/time_format.hpp"

namespace vicc_anatomy_viz {
namespace {

TEST(TimeFormatTest, ParsesDatesTimesAndOffsets) {
  EXPECT_EQ(parseTimestamp("1970-01-01"), 0);
  EXPECT_EQ(parseTimestamp("2023-03-06T09:15:00Z"), 1678094100);
  EXPECT_EQ(parseTimestamp("2023-03-06T09:15"), 1678094100);
  EXPECT_EQ(parseTimestamp("2023-03-06T10:15:00+01:00"), 1678094100);
  EXPECT_EQ(parseTimestamp("2023-03-06T09:15:00.250Z"), 1678094100);
  EXPECT_EQ(parseTimestamp("2024-02-29"), 1709164800);
}

TEST(TimeFormatTest, RejectsMalformedAndImpossibleTimes) {
  for (const char* text : {"", "2023-3-6", "2023-02-29", "2023-13-01", "2023-03-06T25:00",
                           "2023-03-06T09:15:00+1", "06.03.2023", "2023-03-06T09:15:00Zx"}) {
    EXPECT_FALSE(parseTimestamp(text).has_value()) << text;
  }
}

TEST(TimeFormatTest, ADateAloneIsTheEndOfThatDayAsUpperBound) {
  EXPECT_EQ(parseUpperBound("2023-03-06"), *parseTimestamp("2023-03-06") + 86399);
  EXPECT_EQ(parseUpperBound("2023-03-06T09:15:00Z"), 1678094100);
}

TEST(TimeFormatTest, FormatsUtcAndRoundTrips) {
  EXPECT_EQ(formatTimestamp(1678094100), "2023-03-06T09:15:00Z");
  EXPECT_EQ(formatTimestamp(-1), "1969-12-31T23:59:59Z");
  EXPECT_EQ(parseTimestamp(formatTimestamp(1709164800 + 4321)), 1709164800 + 4321);
}

}  // namespace
}  // namespace vicc_anatomy_viz
