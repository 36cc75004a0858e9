#include "svg_color.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <map>
#include <stdexcept>

namespace vicc_glyphs {
namespace io_detail {
namespace {

std::string trimmedLower(const std::string& text) {
  const auto begin = text.find_first_not_of(" \t\r\n");
  if (begin == std::string::npos) return {};
  const auto end = text.find_last_not_of(" \t\r\n");
  std::string result = text.substr(begin, end - begin + 1);
  std::transform(result.begin(), result.end(), result.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return result;
}

Color rgb255(int r, int g, int b) { return Color(r, g, b) / 255.0; }

const std::map<std::string, Color>& namedColors() {
  static const std::map<std::string, Color> colors = {
      {"black", rgb255(0, 0, 0)},       {"silver", rgb255(192, 192, 192)},
      {"gray", rgb255(128, 128, 128)},  {"grey", rgb255(128, 128, 128)},
      {"white", rgb255(255, 255, 255)}, {"maroon", rgb255(128, 0, 0)},
      {"red", rgb255(255, 0, 0)},       {"purple", rgb255(128, 0, 128)},
      {"fuchsia", rgb255(255, 0, 255)}, {"magenta", rgb255(255, 0, 255)},
      {"green", rgb255(0, 128, 0)},     {"lime", rgb255(0, 255, 0)},
      {"olive", rgb255(128, 128, 0)},   {"yellow", rgb255(255, 255, 0)},
      {"navy", rgb255(0, 0, 128)},      {"blue", rgb255(0, 0, 255)},
      {"teal", rgb255(0, 128, 128)},    {"aqua", rgb255(0, 255, 255)},
      {"cyan", rgb255(0, 255, 255)},    {"orange", rgb255(255, 165, 0)},
  };
  return colors;
}

int hexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  throw std::invalid_argument(std::string("bad hex digit '") + c + "'");
}

Color parseHex(const std::string& hex) {
  if (hex.size() == 3) {
    return rgb255(hexDigit(hex[0]) * 17, hexDigit(hex[1]) * 17, hexDigit(hex[2]) * 17);
  }
  if (hex.size() == 6) {
    return rgb255(hexDigit(hex[0]) * 16 + hexDigit(hex[1]),
                  hexDigit(hex[2]) * 16 + hexDigit(hex[3]),
                  hexDigit(hex[4]) * 16 + hexDigit(hex[5]));
  }
  throw std::invalid_argument("hex colour needs 3 or 6 digits");
}

// One rgb() channel: a number in 0..255 or a percentage; clamped like CSS does.
double parseChannel(std::string text) {
  text = trimmedLower(text);
  const bool percent = !text.empty() && text.back() == '%';
  if (percent) text.pop_back();
  double value = 0.0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || result.ec != std::errc() || result.ptr != text.data() + text.size() ||
      !std::isfinite(value)) {
    throw std::invalid_argument("bad rgb() channel '" + text + "'");
  }
  return std::clamp(percent ? value / 100.0 : value / 255.0, 0.0, 1.0);
}

Color parseRgbFunction(const std::string& value) {
  const auto open = value.find('(');
  const auto close = value.rfind(')');
  if (open == std::string::npos || close == std::string::npos || close < open ||
      close != value.size() - 1) {
    throw std::invalid_argument("unbalanced rgb()");
  }
  const std::string inner = value.substr(open + 1, close - open - 1);
  Color color;
  std::size_t start = 0;
  for (int i = 0; i < 3; ++i) {
    const auto comma = inner.find(',', start);
    if ((i < 2) != (comma != std::string::npos))
      throw std::invalid_argument("rgb() needs 3 values");
    color[i] = parseChannel(
        inner.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    start = comma + 1;
  }
  return color;
}

}  // namespace

std::optional<Color> parseSvgPaint(const std::string& raw) {
  const std::string value = trimmedLower(raw);
  if (value == "none" || value == "transparent") return std::nullopt;
  if (!value.empty() && value[0] == '#') return parseHex(value.substr(1));
  if (value.rfind("rgb(", 0) == 0) return parseRgbFunction(value);
  const auto named = namedColors().find(value);
  if (named != namedColors().end()) return named->second;
  throw std::invalid_argument("unsupported paint '" + raw.substr(0, 40) + "'");
}

}  // namespace io_detail
}  // namespace vicc_glyphs
