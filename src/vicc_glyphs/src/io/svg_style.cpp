#include "svg_style.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "svg_color.hpp"

namespace vicc_glyphs {
namespace io_detail {
namespace {

std::string trim(const std::string& text) {
  const auto begin = text.find_first_not_of(" \t\r\n");
  if (begin == std::string::npos) return {};
  return text.substr(begin, text.find_last_not_of(" \t\r\n") - begin + 1);
}

void apply(const std::string& name, const std::string& raw_value, SvgStyle& style) {
  const std::string value = trim(raw_value);
  if (value == "inherit") return;  // the parent's value is already in `style`
  if (name == "fill") {
    style.fill = parseSvgPaint(value);
  } else if (name == "fill-rule") {
    if (value == "evenodd") {
      style.rule = FillRule::kEvenOdd;
    } else if (value == "nonzero") {
      style.rule = FillRule::kNonZero;
    } else {
      throw std::invalid_argument("unknown fill-rule '" + value + "'");
    }
  } else if (name == "display") {
    style.displayed = value != "none";
  } else if (name == "visibility") {
    style.visible = value == "visible";
  }
}

}  // namespace

SvgStyle cascadeStyle(const tinyxml2::XMLElement& element, const SvgStyle& parent) {
  SvgStyle style = parent;
  style.displayed = true;  // display is not inherited; a hidden parent is skipped as a whole
  for (const char* name : {"fill", "fill-rule", "display", "visibility"}) {
    if (const char* value = element.Attribute(name)) apply(name, value, style);
  }
  if (const char* declarations = element.Attribute("style")) {
    const std::string text(declarations);
    std::size_t start = 0;
    while (start <= text.size()) {
      const auto end = std::min(text.find(';', start), text.size());
      const std::string declaration = text.substr(start, end - start);
      const auto colon = declaration.find(':');
      if (colon != std::string::npos) {
        apply(trim(declaration.substr(0, colon)), declaration.substr(colon + 1), style);
      } else if (!trim(declaration).empty()) {
        throw std::invalid_argument("style declaration without ':' '" + declaration + "'");
      }
      start = end + 1;
    }
  }
  return style;
}

}  // namespace io_detail
}  // namespace vicc_glyphs
