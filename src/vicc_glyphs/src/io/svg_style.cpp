#include "svg_style.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

#include "svg_color.hpp"
#include "svg_number_scanner.hpp"

namespace vicc_glyphs {
namespace io_detail {
namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// "url(#id)" (optionally quoted, optionally with a fallback after it) to "id".
std::string referencedId(const std::string& value) {
  const auto open = value.find('(');
  const auto close = value.find(')');
  if (value.rfind("url(", 0) != 0 || close == std::string::npos) {
    throw std::invalid_argument("bad url() '" + value.substr(0, 40) + "'");
  }
  std::string inner = value.substr(open + 1, close - open - 1);
  inner.erase(std::remove_if(inner.begin(), inner.end(),
                             [](char c) { return c == '"' || c == '\'' || c == ' '; }),
              inner.end());
  if (inner.empty() || inner[0] != '#') {
    throw std::invalid_argument("only local references url(#id) are supported: '" +
                                value.substr(0, 40) + "'");
  }
  return inner.substr(1);
}

SvgPaint parsePaint(const std::string& value) {
  const std::string key = lower(value);
  if (key == "currentcolor") return {SvgPaint::Kind::kCurrentColor, Color::Zero(), {}};
  if (key.rfind("url(", 0) == 0)
    return {SvgPaint::Kind::kReference, Color::Zero(), referencedId(value)};
  const std::optional<Color> color = parseSvgPaint(value);
  if (!color) return {};
  return {SvgPaint::Kind::kColor, *color, {}};
}

double parseNumber(const std::string& name, const std::string& value) {
  std::string text = value;
  if (text.size() > 2 && text.compare(text.size() - 2, 2, "px") == 0) text.resize(text.size() - 2);
  SvgNumberScanner scanner(text);
  const double number = scanner.number();
  if (!scanner.atEnd() || !std::isfinite(number)) {
    throw std::invalid_argument("unsupported " + name + " '" + value.substr(0, 40) + "'");
  }
  return number;
}

// opacity values: a number or a percentage, clamped to [0, 1].
double parseOpacity(const std::string& name, const std::string& value) {
  const bool percent = !value.empty() && value.back() == '%';
  const double number = parseNumber(name, percent ? value.substr(0, value.size() - 1) : value);
  return std::clamp(percent ? number / 100.0 : number, 0.0, 1.0);
}

FillRule parseRule(const std::string& name, const std::string& value) {
  if (value == "evenodd") return FillRule::kEvenOdd;
  if (value == "nonzero") return FillRule::kNonZero;
  throw std::invalid_argument("unknown " + name + " '" + value + "'");
}

std::vector<double> parseDashes(const std::string& value) {
  if (value == "none") return {};
  std::vector<double> dashes;
  SvgNumberScanner scanner(value);
  while (scanner.numberAhead()) dashes.push_back(scanner.number());
  if (!scanner.atEnd() || std::any_of(dashes.begin(), dashes.end(),
                                      [](double d) { return !(d >= 0.0) || !std::isfinite(d); })) {
    throw std::invalid_argument("unsupported stroke-dasharray '" + value.substr(0, 40) + "'");
  }
  if (std::all_of(dashes.begin(), dashes.end(), [](double d) { return d == 0.0; })) return {};
  if (dashes.size() % 2 == 1) dashes.insert(dashes.end(), dashes.begin(), dashes.end());
  return dashes;
}

template <typename Enum>
Enum parseKeyword(const std::string& name, const std::string& value,
                  const std::map<std::string, Enum>& keywords) {
  const auto found = keywords.find(value);
  if (found == keywords.end()) throw std::invalid_argument("unknown " + name + " '" + value + "'");
  return found->second;
}

void applyStroke(const std::string& name, const std::string& value, StrokeGeometry& stroke) {
  if (name == "stroke-width") {
    stroke.width = parseNumber(name, value);
    if (stroke.width < 0.0) throw std::invalid_argument("negative stroke-width");
  } else if (name == "stroke-linecap") {
    stroke.cap = parseKeyword<LineCap>(
        name, value,
        {{"butt", LineCap::kButt}, {"round", LineCap::kRound}, {"square", LineCap::kSquare}});
  } else if (name == "stroke-linejoin") {
    stroke.join = parseKeyword<LineJoin>(name, value,
                                         {{"miter", LineJoin::kMiter},
                                          {"miter-clip", LineJoin::kMiter},
                                          {"arcs", LineJoin::kMiter},
                                          {"round", LineJoin::kRound},
                                          {"bevel", LineJoin::kBevel}});
  } else if (name == "stroke-miterlimit") {
    stroke.miter_limit = parseNumber(name, value);
  } else if (name == "stroke-dasharray") {
    stroke.dashes = parseDashes(value);
  } else if (name == "stroke-dashoffset") {
    stroke.dash_offset = parseNumber(name, value);
  }
}

// Unimplemented properties at values other than their no-effect defaults.
bool changesThePicture(const std::string& name, const std::string& value) {
  static const std::map<std::string, std::string> neutral = {
      {"marker", "none"},           {"marker-start", "none"},  {"marker-mid", "none"},
      {"marker-end", "none"},       {"vector-effect", "none"}, {"paint-order", "normal"},
      {"mix-blend-mode", "normal"}, {"transform", "none"},
  };
  const auto found = neutral.find(name);
  return found != neutral.end() && !found->second.empty() && lower(value) != found->second;
}

std::string unlessNone(const std::string& value) { return value == "none" ? std::string() : value; }

std::string trim(const std::string& text) {
  const auto begin = text.find_first_not_of(" \t\r\n");
  if (begin == std::string::npos) return {};
  return text.substr(begin, text.find_last_not_of(" \t\r\n") - begin + 1);
}

void apply(const std::string& name, const std::string& raw_value, const SvgStyle& parent,
           SvgStyle& style) {
  const std::string trimmed = trim(raw_value);
  const std::string value =
      lower(trimmed) == "currentcolor" && name == "color" ? std::string("inherit") : trimmed;
  if (value == "inherit") return;  // the parent's value is already in `style` (if inherited)
  if (name == "fill") {
    style.fill = parsePaint(value);
  } else if (name == "fill-opacity") {
    style.fill_opacity = parseOpacity(name, value);
  } else if (name == "fill-rule") {
    style.rule = parseRule(name, value);
  } else if (name == "stroke") {
    style.stroke = parsePaint(value);
  } else if (name == "stroke-opacity") {
    style.stroke_opacity = parseOpacity(name, value);
  } else if (name.rfind("stroke-", 0) == 0) {
    applyStroke(name, value, style.stroke_geometry);
  } else if (name == "color") {
    const std::optional<Color> color = parseSvgPaint(value);
    style.color = color ? *color : parent.color;
  } else if (name == "clip-rule") {
    style.clip_rule = parseRule(name, value);
  } else if (name == "display") {
    style.displayed = value != "none";
  } else if (name == "visibility") {
    style.visible = value == "visible";
  } else if (name == "opacity") {
    style.opacity = parseOpacity(name, value);
  } else if (name == "clip-path") {
    style.clip_path = value == "none" ? std::string() : referencedId(value);
  } else if (name == "mask") {
    style.mask = unlessNone(value);
  } else if (name == "filter") {
    style.filter = unlessNone(value);
  } else if (changesThePicture(name, value)) {
    style.unsupported = name + ": " + value;
  }
}

const char* const kPresentationAttributes[] = {"fill",
                                               "fill-opacity",
                                               "fill-rule",
                                               "stroke",
                                               "stroke-opacity",
                                               "stroke-width",
                                               "stroke-linecap",
                                               "stroke-linejoin",
                                               "stroke-miterlimit",
                                               "stroke-dasharray",
                                               "stroke-dashoffset",
                                               "color",
                                               "clip-rule",
                                               "display",
                                               "visibility",
                                               "opacity",
                                               "clip-path",
                                               "mask",
                                               "filter",
                                               "marker-start",
                                               "marker-mid",
                                               "marker-end",
                                               "vector-effect",
                                               "paint-order",
                                               "mix-blend-mode"};

}  // namespace

SvgStyle cascadeStyle(const tinyxml2::XMLElement& element, const SvgStyle& parent,
                      const StyleSheet& sheet) {
  SvgStyle style = parent;
  // Not inherited: each element starts from the initial values.
  style.displayed = true;
  style.opacity = 1.0;
  style.clip_path.clear();
  style.mask.clear();
  style.filter.clear();
  style.unsupported.clear();
  for (const char* name : kPresentationAttributes) {
    if (const char* value = element.Attribute(name)) apply(name, value, parent, style);
  }
  if (!sheet.empty()) {
    for (const CssDeclaration& d : sheet.matching(element)) apply(d.name, d.value, parent, style);
  }
  if (const char* declarations = element.Attribute("style")) {
    for (const CssDeclaration& d : parseDeclarations(declarations)) {
      apply(d.name, d.value, parent, style);
    }
  }
  return style;
}

std::optional<Color> paintColor(const SvgPaint& paint, const SvgStyle& style) {
  switch (paint.kind) {
    case SvgPaint::Kind::kColor:
      return paint.color;
    case SvgPaint::Kind::kCurrentColor:
      return style.color;
    case SvgPaint::Kind::kNone:
    case SvgPaint::Kind::kReference:
      break;
  }
  return std::nullopt;
}

}  // namespace io_detail
}  // namespace vicc_glyphs
