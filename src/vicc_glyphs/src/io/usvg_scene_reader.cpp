// Reader of small-usvg's SceneXML format (conventions in usvg_scene_xml.hpp).

#include <tinyxml2.h>

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include "text_file.hpp"
#include "vicc_glyphs/io/usvg_scene_xml.hpp"
#include "xml_attributes.hpp"

namespace vicc_glyphs {
namespace {

using io_detail::requireDouble;
using io_detail::requireInt;
using tinyxml2::XMLElement;

constexpr double kByteColorScale = 255.0;
constexpr const char* kBarrierBoundary = "Neumann";

// A colour point as stored: file globalID (normalised per set later) and RGB in [0, 1].
struct RawColor {
  double global_id = 0.0;
  Color rgb = Color::Zero();
};

class UsvgSceneReader {
 public:
  explicit UsvgSceneReader(std::string source) : source_(std::move(source)) {}

  DiffusionCurveImage read(const std::string& text) {
    tinyxml2::XMLDocument document;
    const XMLElement& root = io_detail::parseCurveFileRoot(document, text, source_, "scene",
                                                           "a <scene> root element (SceneXML)");
    // <poisson_curve_set> and <mesh_set> have no counterpart in our representation; they are
    // skipped (documented in usvg_scene_xml.hpp), only the diffusion curves are read.
    DiffusionCurveImage image;
    io_detail::requireImageSize(root, source_, "scene", image.width, image.height);
    if (const XMLElement* set = root.FirstChildElement("curve_set")) {
      for (const XMLElement* curve : children(*set, "curve", *set, "nb_curves", "curve_set")) {
        image.curves.push_back(readCurve(*curve, "curve " + std::to_string(image.curves.size())));
      }
    }
    const std::string problem = validate(image);
    if (!problem.empty()) throw FormatError(source_, "", problem);
    return image;
  }

 private:
  // The child elements `name` of `parent`. As in small-usvg, a count attribute on `owner`
  // (nb_*) says how many to read: fewer present is an error (truncation), extra ones are ignored
  // (the vendored ladybug's curve 55 declares 5 right colours and lists 6). Without the
  // attribute all are read.
  std::vector<const XMLElement*> children(const XMLElement& parent, const char* name,
                                          const XMLElement& owner, const char* count_attribute,
                                          const std::string& place) const {
    std::vector<const XMLElement*> found;
    for (const XMLElement* e = parent.FirstChildElement(name); e; e = e->NextSiblingElement(name)) {
      found.push_back(e);
    }
    if (!owner.Attribute(count_attribute)) return found;
    const int declared = requireInt(owner, count_attribute, source_, place);
    if (declared < 0 || static_cast<std::size_t>(declared) > found.size()) {
      throw FormatError(source_, place,
                        std::string(count_attribute) + "=" + std::to_string(declared) + " but " +
                            std::to_string(found.size()) + " <" + name + "> found");
    }
    found.resize(static_cast<std::size_t>(declared));
    return found;
  }

  DiffusionCurve readCurve(const XMLElement& element, const std::string& place) {
    DiffusionCurve curve;
    readControlPoints(io_detail::requireChild(element, "control_points_set", source_, place),
                      element, place, curve);
    const int segments = io_detail::requireDrawableSegments(curve, source_, place);
    const XMLElement& file_left =
        io_detail::requireChild(element, "left_colors_set", source_, place);
    const XMLElement& file_right =
        io_detail::requireChild(element, "right_colors_set", source_, place);
    const std::vector<RawColor> left =
        readColors(file_left, "left_color", element, "nb_left_colors", place);
    const std::vector<RawColor> right =
        readColors(file_right, "right_color", element, "nb_right_colors", place);
    // The file's left is the (-dy, dx) side, which is our right (see usvg_scene_xml.hpp).
    curve.right_colors = placeColors(left, segments);
    curve.left_colors = placeColors(right, segments);
    curve.right_emits = !isBarrier(file_left);
    curve.left_emits = !isBarrier(file_right);
    return curve;
  }

  void readControlPoints(const XMLElement& set, const XMLElement& curve_element,
                         const std::string& place, DiffusionCurve& curve) {
    for (const XMLElement* point :
         children(set, "control_point", curve_element, "nb_control_points", place)) {
      if (++total_points_ > kMaxControlPointsPerFile) {
        throw FormatError(source_, place, io_detail::tooManyControlPointsMessage());
      }
      const std::string point_place =
          place + " control point " + std::to_string(curve.control_points.size());
      curve.control_points.emplace_back(requireDouble(*point, "x", source_, point_place),
                                        requireDouble(*point, "y", source_, point_place));
    }
  }

  static bool isBarrier(const XMLElement& color_set) {
    const char* boundary = color_set.Attribute("boundary");
    return boundary && std::string(boundary) == kBarrierBoundary;
  }

  // One channel: uppercase name in 0..255, else the lowercase name in 0..1 (as small-usvg).
  double readChannel(const XMLElement& element, const char* upper, const std::string& place) const {
    const bool bytes = element.Attribute(upper) != nullptr;
    const std::string lower(1, static_cast<char>(std::tolower(static_cast<unsigned char>(*upper))));
    const double scale = bytes ? kByteColorScale : 1.0;
    const double value = requireDouble(element, bytes ? upper : lower.c_str(), source_, place);
    if (value < 0.0 || value > scale) {
      throw FormatError(source_, place,
                        std::string("colour channel ") + (bytes ? upper : lower.c_str()) +
                            (bytes ? " outside 0..255" : " outside 0..1"));
    }
    return value / scale;
  }

  std::vector<RawColor> readColors(const XMLElement& set, const char* name,
                                   const XMLElement& curve_element, const char* count_attribute,
                                   const std::string& curve_place) const {
    std::vector<RawColor> colors;
    for (const XMLElement* c : children(set, name, curve_element, count_attribute, curve_place)) {
      const std::string place = curve_place + " " + name + " " + std::to_string(colors.size());
      RawColor color;
      color.global_id = requireDouble(*c, "globalID", source_, place);
      if (color.global_id < 0.0) throw FormatError(source_, place, "negative globalID");
      color.rgb = Color(readChannel(*c, "R", place), readChannel(*c, "G", place),
                        readChannel(*c, "B", place));
      colors.push_back(color);
    }
    if (colors.empty()) throw FormatError(source_, curve_place, std::string("no <") + name + ">");
    return colors;
  }

  // globalIDs are normalised by the set's largest one when it exceeds 1 (small-usvg's rule), so
  // the set always spans the whole curve: s = K * globalID / max.
  static std::vector<ColorPoint> placeColors(const std::vector<RawColor>& raw, int segments) {
    double largest = 1.0;
    for (const RawColor& c : raw) largest = std::max(largest, c.global_id);
    std::vector<ColorPoint> points;
    for (const RawColor& c : raw) points.push_back({segments * c.global_id / largest, c.rgb});
    std::stable_sort(points.begin(), points.end(), [](const ColorPoint& a, const ColorPoint& b) {
      return a.position < b.position;
    });
    return points;
  }

  std::string source_;
  std::size_t total_points_ = 0;
};

// Skips whitespace, the XML declaration, processing instructions, DOCTYPE and comments.
std::size_t firstElementStart(const std::string& text) {
  std::size_t at = 0;
  while (at < text.size()) {
    if (std::isspace(static_cast<unsigned char>(text[at]))) {
      ++at;
    } else if (text.compare(at, 4, "<!--") == 0) {
      at = text.find("-->", at + 4);
      if (at == std::string::npos) return at;
      at += 3;
    } else if (text.compare(at, 2, "<?") == 0 || text.compare(at, 2, "<!") == 0) {
      at = text.find('>', at + 2);
      if (at == std::string::npos) return at;
      ++at;
    } else {
      return text[at] == '<' ? at : std::string::npos;
    }
  }
  return std::string::npos;
}

}  // namespace

DiffusionCurveImage parseUsvgSceneXml(const std::string& text, const std::string& source) {
  return UsvgSceneReader(source).read(text);
}

DiffusionCurveImage readUsvgSceneXml(const std::string& path) {
  return UsvgSceneReader(path).read(io_detail::readTextFile(path));
}

bool hasUsvgSceneRoot(const std::string& text) {
  const std::size_t start = firstElementStart(text);
  if (start == std::string::npos) return false;
  const std::string name = "<scene";
  if (text.compare(start, name.size(), name) != 0) return false;
  const std::size_t after = start + name.size();
  return after < text.size() && (std::isspace(static_cast<unsigned char>(text[after])) ||
                                 text[after] == '>' || text[after] == '/');
}

}  // namespace vicc_glyphs
