#pragma once
// ISO 8601 / FHIR dateTime timestamps of examinations, in UTC microseconds. Sub-second
// precision is kept (two readings a fraction of a second apart must not collide), impossible
// offsets and leap seconds are rejected instead of being bent into a nearby time, and a time
// without an offset is reported so that importers can warn about it.

#include <cstdint>
#include <optional>
#include <string>

namespace vicc_anatomy_viz {

/// Microseconds since the Unix epoch, UTC.
using TimestampUs = std::int64_t;
constexpr TimestampUs kMicrosPerSecond = 1000000;

struct ParsedTime {
  TimestampUs us = 0;
  bool date_only = false;   ///< "YYYY-MM-DD": midnight UTC
  bool has_offset = false;  ///< "Z" or "+HH:MM" given; false: taken as UTC (warn)
};

/// Parses "YYYY-MM-DD" or "YYYY-MM-DDTHH:MM[:SS[.ffffff]][Z|+HH:MM|-HH:MM]". On failure returns
/// nullopt and, with `problem`, says why (malformed, impossible date, offset beyond +-14:00,
/// a leap second, more precision than a microsecond).
std::optional<ParsedTime> parseTime(const std::string& text, std::string* problem = nullptr);

/// parseTime(text)->us.
std::optional<TimestampUs> parseTimestamp(const std::string& text);

/// Upper bound for "the examination at or before `text`": a date alone means the end of that
/// day, a time without fraction the end of that second, so an examination within counts.
std::optional<TimestampUs> parseUpperBound(const std::string& text);

/// Which examination times are plausible: not before `min_year`, not more than
/// `max_future_seconds` ahead of the clock (clock skew, time zones).
struct TimePlausibility {
  int min_year = 1900;
  std::int64_t max_future_seconds = 24 * 3600;
  std::optional<TimestampUs> now;  ///< tests; default: the system clock

  /// "" when plausible, else why (names the time, not a patient).
  std::string problem(TimestampUs time) const;
  void validate() const;  ///< throws std::invalid_argument
};

/// "2023-03-06T08:30:00Z"; with a fraction when there is one ("...:00.25Z", "...:00.000001Z").
std::string formatTimestamp(TimestampUs time);

/// Whole seconds (floor) and the microseconds within the second, for ROS times.
std::int64_t wholeSeconds(TimestampUs time);
std::int64_t microsWithinSecond(TimestampUs time);

}  // namespace vicc_anatomy_viz
