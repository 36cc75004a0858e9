#include "vicc_anatomy_viz/time_format.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>

namespace vicc_anatomy_viz {

namespace {

// Days since 1970-01-01 of a proleptic Gregorian date (H. Hinnant's algorithm).
std::int64_t daysFromCivil(std::int64_t y, unsigned m, unsigned d) {
  y -= m <= 2;
  const std::int64_t era = (y >= 0 ? y : y - 399) / 400;
  const unsigned yoe = static_cast<unsigned>(y - era * 400);
  const unsigned doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + static_cast<std::int64_t>(doe) - 719468;
}

void civilFromDays(std::int64_t z, int& y, unsigned& m, unsigned& d) {
  z += 719468;
  const std::int64_t era = (z >= 0 ? z : z - 146096) / 146097;
  const unsigned doe = static_cast<unsigned>(z - era * 146097);
  const unsigned yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  const unsigned doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const unsigned mp = (5 * doy + 2) / 153;
  d = doy - (153 * mp + 2) / 5 + 1;
  m = mp < 10 ? mp + 3 : mp - 9;
  y = static_cast<int>(yoe + era * 400 + (m <= 2));
}

unsigned daysInMonth(int year, unsigned month) {
  static const unsigned kDays[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
  return month == 2 && leap ? 29 : kDays[month - 1];
}

/// Reads exactly `count` digits at `pos`.
bool digits(const std::string& text, std::size_t pos, std::size_t count, int& value) {
  if (pos + count > text.size()) return false;
  value = 0;
  for (std::size_t i = pos; i < pos + count; ++i) {
    if (!std::isdigit(static_cast<unsigned char>(text[i]))) return false;
    value = value * 10 + (text[i] - '0');
  }
  return true;
}

struct Parsed {
  std::int64_t seconds = 0;
  bool date_only = false;
};

std::optional<Parsed> parse(const std::string& text) {
  int year = 0, month = 0, day = 0;
  if (text.size() < 10 || !digits(text, 0, 4, year) || text[4] != '-' ||
      !digits(text, 5, 2, month) || text[7] != '-' || !digits(text, 8, 2, day)) {
    return std::nullopt;
  }
  if (year < 1900 || month < 1 || month > 12 || day < 1 ||
      day > static_cast<int>(daysInMonth(year, static_cast<unsigned>(month)))) {
    return std::nullopt;
  }
  Parsed parsed;
  parsed.seconds =
      daysFromCivil(year, static_cast<unsigned>(month), static_cast<unsigned>(day)) * 86400;
  if (text.size() == 10) {
    parsed.date_only = true;
    return parsed;
  }
  int hour = 0, minute = 0, second = 0;
  std::size_t pos = 10;
  if ((text[pos] != 'T' && text[pos] != ' ') || !digits(text, pos + 1, 2, hour) ||
      text.size() < pos + 6 || text[pos + 3] != ':' || !digits(text, pos + 4, 2, minute)) {
    return std::nullopt;
  }
  pos += 6;
  if (pos < text.size() && text[pos] == ':') {
    if (!digits(text, pos + 1, 2, second)) return std::nullopt;
    pos += 3;
    if (pos < text.size() && text[pos] == '.') {  // fractions of a second are dropped
      ++pos;
      const std::size_t start = pos;
      while (pos < text.size() && std::isdigit(static_cast<unsigned char>(text[pos]))) ++pos;
      if (pos == start) return std::nullopt;
    }
  }
  if (hour > 23 || minute > 59 || second > 60) return std::nullopt;
  std::int64_t offset = 0;
  if (pos < text.size()) {
    if (text[pos] == 'Z' && pos + 1 == text.size()) {
      pos += 1;
    } else if (text[pos] == '+' || text[pos] == '-') {
      int oh = 0, om = 0;
      if (text.size() != pos + 6 || !digits(text, pos + 1, 2, oh) || text[pos + 3] != ':' ||
          !digits(text, pos + 4, 2, om) || oh > 23 || om > 59) {
        return std::nullopt;
      }
      offset = (text[pos] == '+' ? 1 : -1) * (oh * 3600 + om * 60);
      pos = text.size();
    } else {
      return std::nullopt;
    }
  }
  if (pos != text.size()) return std::nullopt;
  parsed.seconds += hour * 3600 + minute * 60 + std::min(second, 59) - offset;
  return parsed;
}

}  // namespace

std::optional<std::int64_t> parseTimestamp(const std::string& text) {
  const auto parsed = parse(text);
  if (!parsed) return std::nullopt;
  return parsed->seconds;
}

std::optional<std::int64_t> parseUpperBound(const std::string& text) {
  const auto parsed = parse(text);
  if (!parsed) return std::nullopt;
  return parsed->date_only ? parsed->seconds + 86399 : parsed->seconds;
}

std::string formatTimestamp(std::int64_t seconds) {
  std::int64_t days = seconds / 86400;
  std::int64_t rest = seconds % 86400;
  if (rest < 0) {
    rest += 86400;
    days -= 1;
  }
  int year = 0;
  unsigned month = 0, day = 0;
  civilFromDays(days, year, month, day);
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%04d-%02u-%02uT%02d:%02d:%02dZ", year, month, day,
                static_cast<int>(rest / 3600), static_cast<int>(rest % 3600 / 60),
                static_cast<int>(rest % 60));
  return buffer;
}

}  // namespace vicc_anatomy_viz
