#pragma once
// Scanner for the number lists of SVG attributes (path data, transforms, points, viewBox):
// SVG number grammar only (no inf/nan/hex), separators are whitespace and at most one comma.

#include <optional>
#include <string>

namespace vicc_glyphs {
namespace io_detail {

class SvgNumberScanner {
 public:
  explicit SvgNumberScanner(const std::string& text) : text_(text) {}

  /// Skips whitespace and an optional single comma.
  void skipSeparators();
  /// True when only whitespace is left.
  bool atEnd();
  /// True if a number starts here (after separators).
  bool numberAhead();
  /// Reads a number; throws std::invalid_argument with the offset when there is none or it is
  /// not finite.
  double number();
  /// Reads an arc flag: a single '0' or '1' (they may be written without separators).
  bool flag();
  /// The next non-separator character (0 at the end), without consuming it.
  char peek();
  /// Consumes one character.
  void advance() { ++position_; }
  std::size_t position() const { return position_; }

 private:
  void skipWhitespace();
  [[noreturn]] void fail(const std::string& what) const;

  const std::string& text_;
  std::size_t position_ = 0;
};

}  // namespace io_detail
}  // namespace vicc_glyphs
