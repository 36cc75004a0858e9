#pragma once
// ISO 8601 timestamps of examinations, in UTC seconds.

#include <cstdint>
#include <optional>
#include <string>

namespace vicc_anatomy_viz {

/// Parses "YYYY-MM-DD", "YYYY-MM-DDTHH:MM[:SS[.fff]]" with optional "Z" or "+HH:MM"/"-HH:MM"
/// (no offset = UTC). A date alone is its midnight. nullopt if malformed or impossible.
std::optional<std::int64_t> parseTimestamp(const std::string& text);

/// Upper bound for "the examination at or before `text`": a date alone means the end of that
/// day, so an examination on that day counts.
std::optional<std::int64_t> parseUpperBound(const std::string& text);

/// "2023-03-06T08:30:00Z".
std::string formatTimestamp(std::int64_t seconds);

}  // namespace vicc_anatomy_viz
