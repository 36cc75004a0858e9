#include "svg_number_scanner.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <stdexcept>

namespace vicc_glyphs {
namespace io_detail {
namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f'; }
bool isDigit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

void SvgNumberScanner::skipWhitespace() {
  while (position_ < text_.size() && isSpace(text_[position_])) ++position_;
}

void SvgNumberScanner::skipSeparators() {
  skipWhitespace();
  if (position_ < text_.size() && text_[position_] == ',') {
    ++position_;
    skipWhitespace();
  }
}

bool SvgNumberScanner::atEnd() {
  skipWhitespace();
  return position_ >= text_.size();
}

char SvgNumberScanner::peek() {
  skipWhitespace();
  return position_ < text_.size() ? text_[position_] : '\0';
}

bool SvgNumberScanner::numberAhead() {
  skipSeparators();
  if (position_ >= text_.size()) return false;
  const char c = text_[position_];
  return isDigit(c) || c == '.' || c == '-' || c == '+';
}

void SvgNumberScanner::fail(const std::string& what) const {
  throw std::invalid_argument(what + " at offset " + std::to_string(position_));
}

double SvgNumberScanner::number() {
  skipSeparators();
  const std::size_t start = position_;
  std::size_t i = position_;
  if (i < text_.size() && (text_[i] == '+' || text_[i] == '-')) ++i;
  const std::size_t digits_start = i;
  while (i < text_.size() && isDigit(text_[i])) ++i;
  bool has_digits = i > digits_start;
  if (i < text_.size() && text_[i] == '.') {
    ++i;
    const std::size_t fraction_start = i;
    while (i < text_.size() && isDigit(text_[i])) ++i;
    has_digits = has_digits || i > fraction_start;
  }
  if (!has_digits) fail("expected a number");
  if (i < text_.size() && (text_[i] == 'e' || text_[i] == 'E')) {
    std::size_t j = i + 1;
    if (j < text_.size() && (text_[j] == '+' || text_[j] == '-')) ++j;
    const std::size_t exponent_start = j;
    while (j < text_.size() && isDigit(text_[j])) ++j;
    if (j > exponent_start) i = j;  // otherwise the 'e' belongs to what follows
  }
  // from_chars rejects a leading '+', so skip it.
  const std::size_t parse_from = text_[start] == '+' ? start + 1 : start;
  double value = 0.0;
  const auto result = std::from_chars(text_.data() + parse_from, text_.data() + i, value);
  if (result.ec != std::errc() || result.ptr != text_.data() + i || !std::isfinite(value)) {
    fail("number out of range");
  }
  position_ = i;
  return value;
}

bool SvgNumberScanner::flag() {
  skipSeparators();
  if (position_ < text_.size() && (text_[position_] == '0' || text_[position_] == '1')) {
    return text_[position_++] == '1';
  }
  fail("expected an arc flag 0 or 1");
}

}  // namespace io_detail
}  // namespace vicc_glyphs
