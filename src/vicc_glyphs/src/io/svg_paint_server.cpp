#include "svg_paint_server.hpp"

#include "svg_color.hpp"
#include "svg_css.hpp"

namespace vicc_glyphs {
namespace io_detail {
namespace {

constexpr int kMaxHrefChain = 8;

Color stopColor(const tinyxml2::XMLElement& stop) {
  std::string value = stop.Attribute("stop-color") ? stop.Attribute("stop-color") : "black";
  if (const char* style = stop.Attribute("style")) {
    for (const CssDeclaration& d : parseDeclarations(style)) {
      if (d.name == "stop-color") value = d.value;
    }
  }
  return parseSvgPaint(value).value_or(Color::Zero());
}

}  // namespace

std::optional<Color> gradientMeanColor(
    const tinyxml2::XMLElement& server,
    const std::function<const tinyxml2::XMLElement*(const std::string&)>& lookup) {
  const tinyxml2::XMLElement* gradient = &server;
  for (int hop = 0; hop < kMaxHrefChain && gradient; ++hop) {
    const std::string name = gradient->Name();
    if (name != "linearGradient" && name != "radialGradient") return std::nullopt;
    Color sum = Color::Zero();
    int stops = 0;
    for (const tinyxml2::XMLElement* stop = gradient->FirstChildElement("stop"); stop;
         stop = stop->NextSiblingElement("stop")) {
      sum += stopColor(*stop);
      ++stops;
    }
    if (stops > 0) return Color(sum / stops);
    const char* href = gradient->Attribute("href");
    if (!href) href = gradient->Attribute("xlink:href");
    if (!href || href[0] != '#') return std::nullopt;
    gradient = lookup(href + 1);
  }
  return std::nullopt;
}

}  // namespace io_detail
}  // namespace vicc_glyphs
