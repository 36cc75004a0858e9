#include "vicc_anatomy_viz/time_format.hpp"

#include <cctype>
#include <chrono>
#include <cstdio>
#include <stdexcept>

namespace vicc_anatomy_viz {

namespace {

constexpr std::int64_t kSecondsPerDay = 86400;
/// Real UTC offsets lie within -12:00 .. +14:00 (ISO 8601 allows no more than 14 hours).
constexpr int kMaxOffsetMinutes = 14 * 60;

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

/// Reads a text left to right; the first failure keeps its reason.
class TimeScanner {
 public:
  explicit TimeScanner(const std::string& text) : text_(text) {}

  bool fail(const std::string& why) {
    if (problem_.empty()) problem_ = why;
    return false;
  }
  const std::string& problem() const { return problem_; }
  bool atEnd() const { return pos_ == text_.size(); }

  /// "YYYY-MM-DD" -> days since the epoch.
  bool date(std::int64_t& days) {
    int year = 0, month = 0, day = 0;
    if (!digits(text_, 0, 4, year) || text_.size() < 10 || text_[4] != '-' ||
        !digits(text_, 5, 2, month) || text_[7] != '-' || !digits(text_, 8, 2, day)) {
      return fail("not an ISO 8601 date (YYYY-MM-DD)");
    }
    if (month < 1 || month > 12 || day < 1 ||
        day > static_cast<int>(daysInMonth(year, static_cast<unsigned>(month)))) {
      return fail("no such calendar date");
    }
    days = daysFromCivil(year, static_cast<unsigned>(month), static_cast<unsigned>(day));
    pos_ = 10;
    return true;
  }

  /// "THH:MM[:SS[.f]]" -> microseconds into the day.
  bool clock(std::int64_t& micros) {
    int hour = 0, minute = 0, second = 0;
    if ((text_[pos_] != 'T' && text_[pos_] != ' ') || !digits(text_, pos_ + 1, 2, hour) ||
        text_.size() < pos_ + 6 || text_[pos_ + 3] != ':' || !digits(text_, pos_ + 4, 2, minute)) {
      return fail("time of day is not THH:MM[:SS]");
    }
    pos_ += 6;
    std::int64_t fraction = 0;
    if (pos_ < text_.size() && text_[pos_] == ':') {
      if (!digits(text_, pos_ + 1, 2, second)) return fail("seconds are not two digits");
      pos_ += 3;
      if (!this->fraction(fraction)) return false;
    }
    if (hour > 23 || minute > 59 || second > 60) return fail("no such time of day");
    if (second == 60) {
      return fail(
          "a leap second (:60) cannot be stored exactly; give 23:59:59.999999 or the "
          "next second");
    }
    micros = (hour * 3600 + minute * 60 + second) * kMicrosPerSecond + fraction;
    return true;
  }

  /// "Z" or "+HH:MM"/"-HH:MM" -> seconds east of UTC; nothing -> not given.
  bool offset(std::int64_t& seconds, bool& given) {
    given = false;
    seconds = 0;
    if (atEnd()) return true;
    if (text_[pos_] == 'Z') {
      ++pos_;
      given = true;
      return true;
    }
    if (text_[pos_] != '+' && text_[pos_] != '-') return fail("unexpected text after the time");
    int oh = 0, om = 0;
    if (text_.size() != pos_ + 6 || !digits(text_, pos_ + 1, 2, oh) || text_[pos_ + 3] != ':' ||
        !digits(text_, pos_ + 4, 2, om)) {
      return fail("offset is not +HH:MM or -HH:MM");
    }
    if (om > 59 || oh * 60 + om > kMaxOffsetMinutes) {
      return fail("offset " + text_.substr(pos_) + " is beyond +-14:00");
    }
    seconds = (text_[pos_] == '+' ? 1 : -1) * (oh * 3600 + om * 60);
    pos_ = text_.size();
    given = true;
    return true;
  }

 private:
  /// ".ffffff": up to microseconds; further digits only if they are zeros.
  bool fraction(std::int64_t& micros) {
    micros = 0;
    if (pos_ >= text_.size() || text_[pos_] != '.') return true;
    const std::size_t start = ++pos_;
    while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) {
      const std::size_t place = pos_ - start;
      const int digit = text_[pos_] - '0';
      if (place < 6) {
        micros = micros * 10 + digit;
      } else if (digit != 0) {
        return fail("fraction of a second finer than a microsecond");
      }
      ++pos_;
    }
    if (pos_ == start) return fail("no digits after the decimal point");
    for (std::size_t place = pos_ - start; place < 6; ++place) micros *= 10;
    return true;
  }

  const std::string& text_;
  std::size_t pos_ = 0;
  std::string problem_;
};

}  // namespace

std::optional<ParsedTime> parseTime(const std::string& text, std::string* problem) {
  TimeScanner scanner(text);
  ParsedTime parsed;
  std::int64_t days = 0, micros = 0, offset = 0;
  bool ok = scanner.date(days);
  if (ok && scanner.atEnd()) {
    parsed.date_only = true;
    parsed.has_offset = false;
  } else if (ok) {
    ok = scanner.clock(micros) && scanner.offset(offset, parsed.has_offset) &&
         (scanner.atEnd() || scanner.fail("unexpected text after the time"));
  }
  if (!ok) {
    if (problem) *problem = scanner.problem();
    return std::nullopt;
  }
  parsed.us = (days * kSecondsPerDay - offset) * kMicrosPerSecond + micros;
  return parsed;
}

std::optional<TimestampUs> parseTimestamp(const std::string& text) {
  const auto parsed = parseTime(text);
  if (!parsed) return std::nullopt;
  return parsed->us;
}

std::optional<TimestampUs> parseUpperBound(const std::string& text) {
  const auto parsed = parseTime(text);
  if (!parsed) return std::nullopt;
  if (parsed->date_only) return parsed->us + kSecondsPerDay * kMicrosPerSecond - 1;
  // "09:15" or "09:15:00" covers that whole second; a given fraction is exact.
  const bool has_fraction = text.find('.') != std::string::npos;
  return has_fraction ? parsed->us : parsed->us + kMicrosPerSecond - 1;
}

std::string TimePlausibility::problem(TimestampUs time) const {
  const TimestampUs earliest = daysFromCivil(min_year, 1, 1) * kSecondsPerDay * kMicrosPerSecond;
  if (time < earliest) {
    return formatTimestamp(time) + " is before " + std::to_string(min_year);
  }
  const TimestampUs clock = now ? *now
                                : std::chrono::duration_cast<std::chrono::microseconds>(
                                      std::chrono::system_clock::now().time_since_epoch())
                                      .count();
  if (time > clock + max_future_seconds * kMicrosPerSecond) {
    return formatTimestamp(time) + " lies in the future (more than " +
           std::to_string(max_future_seconds) + " s ahead of the clock)";
  }
  return "";
}

void TimePlausibility::validate() const {
  if (min_year < 0 || min_year > 9999) throw std::invalid_argument("min_year must be 0..9999");
  if (max_future_seconds < 0) throw std::invalid_argument("max_future_seconds must be >= 0");
}

std::int64_t wholeSeconds(TimestampUs time) {
  // Floor division without negating (the most negative time has no positive counterpart).
  return time / kMicrosPerSecond - (time % kMicrosPerSecond < 0 ? 1 : 0);
}

std::int64_t microsWithinSecond(TimestampUs time) {
  const std::int64_t remainder = time % kMicrosPerSecond;
  return remainder < 0 ? remainder + kMicrosPerSecond : remainder;
}

std::string formatTimestamp(TimestampUs time) {
  const std::int64_t seconds = wholeSeconds(time);
  const std::int64_t micros = microsWithinSecond(time);
  std::int64_t days = seconds / kSecondsPerDay;
  std::int64_t rest = seconds % kSecondsPerDay;
  if (rest < 0) {
    rest += kSecondsPerDay;
    days -= 1;
  }
  int year = 0;
  unsigned month = 0, day = 0;
  civilFromDays(days, year, month, day);
  char buffer[48];
  int length = std::snprintf(buffer, sizeof(buffer), "%04d-%02u-%02uT%02d:%02d:%02d", year, month,
                             day, static_cast<int>(rest / 3600), static_cast<int>(rest % 3600 / 60),
                             static_cast<int>(rest % 60));
  if (micros != 0) {
    char fraction[8];
    std::snprintf(fraction, sizeof(fraction), "%06lld", static_cast<long long>(micros));
    std::string digits_text(fraction);
    while (digits_text.back() == '0') digits_text.pop_back();
    length += std::snprintf(buffer + length, sizeof(buffer) - length, ".%s", digits_text.c_str());
  }
  std::snprintf(buffer + length, sizeof(buffer) - length, "Z");
  return buffer;
}

}  // namespace vicc_anatomy_viz
