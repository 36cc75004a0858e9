// Reader of Orzan's XML format (conventions in orzan_conventions.hpp).

#include <tinyxml2.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

#include "orzan_conventions.hpp"
#include "text_file.hpp"
#include "vicc_glyphs/io/orzan_xml.hpp"
#include "xml_attributes.hpp"

namespace vicc_glyphs {
namespace {

using io_detail::requireDouble;
using io_detail::requireInt;
using tinyxml2::XMLElement;

class OrzanReader {
 public:
  explicit OrzanReader(std::string source) : source_(std::move(source)) {}

  DiffusionCurveImage read(const std::string& text) {
    tinyxml2::XMLDocument document;
    const XMLElement& root = io_detail::parseCurveFileRoot(document, text, source_, "curve_set",
                                                           "a <curve_set> root element");
    DiffusionCurveImage image;
    io_detail::requireImageSize(root, source_, "curve_set", image.width, image.height);
    for (const XMLElement* curve = root.FirstChildElement("curve"); curve;
         curve = curve->NextSiblingElement("curve")) {
      image.curves.push_back(readCurve(*curve, "curve " + std::to_string(image.curves.size())));
    }
    checkDeclaredCount(root, "nb_curves", image.curves.size(), "curve_set");
    const std::string problem = validate(image);
    if (!problem.empty()) throw FormatError(source_, "", problem);
    return image;
  }

 private:
  // The nb_* attributes are optional; when present they must match, which catches truncation.
  void checkDeclaredCount(const XMLElement& element, const char* name, std::size_t actual,
                          const std::string& place) const {
    if (!element.Attribute(name)) return;
    const int declared = requireInt(element, name, source_, place);
    if (declared < 0 || static_cast<std::size_t>(declared) != actual) {
      throw FormatError(source_, place,
                        std::string(name) + "=" + std::to_string(declared) + " but " +
                            std::to_string(actual) + " found");
    }
  }

  DiffusionCurve readCurve(const XMLElement& element, const std::string& place) {
    DiffusionCurve curve;
    readControlPoints(io_detail::requireChild(element, "control_points_set", source_, place), place,
                      curve);
    checkDeclaredCount(element, "nb_control_points", curve.control_points.size(), place);
    const int segments = io_detail::requireDrawableSegments(curve, source_, place);

    // The file's left side is our left side (see orzan_conventions.hpp).
    const XMLElement& file_left =
        io_detail::requireChild(element, "left_colors_set", source_, place);
    const XMLElement& file_right =
        io_detail::requireChild(element, "right_colors_set", source_, place);
    curve.left_colors = readColors(file_left, "left_color", segments, place);
    curve.right_colors = readColors(file_right, "right_color", segments, place);
    curve.left_emits = !isBarrier(file_left);
    curve.right_emits = !isBarrier(file_right);
    // An emitting side without colour points would diffuse an arbitrary colour (black).
    for (const auto& [emits, colors, name] :
         {std::tuple{curve.left_emits, &curve.left_colors, "left_colors_set"},
          std::tuple{curve.right_emits, &curve.right_colors, "right_colors_set"}}) {
      if (emits && colors->empty()) {
        throw FormatError(source_, place,
                          std::string(name) +
                              " has no colour points; give at least one or mark the side a "
                              "barrier (boundary=\"Neumann\")");
      }
    }
    checkDeclaredCount(element, "nb_left_colors", curve.left_colors.size(), place);
    checkDeclaredCount(element, "nb_right_colors", curve.right_colors.size(), place);
    if (const XMLElement* blur = element.FirstChildElement("blur_points_set")) {
      curve.blur_points = readBlurPoints(*blur, segments, place);
      checkDeclaredCount(element, "nb_blur_points", curve.blur_points.size(), place);
    }
    return curve;
  }

  void readControlPoints(const XMLElement& set, const std::string& place, DiffusionCurve& curve) {
    for (const XMLElement* point = set.FirstChildElement("control_point"); point;
         point = point->NextSiblingElement("control_point")) {
      if (++total_points_ > kMaxControlPointsPerFile) {
        throw FormatError(source_, place, io_detail::tooManyControlPointsMessage());
      }
      const std::string point_place =
          place + " control point " + std::to_string(curve.control_points.size());
      const double file_x = requireDouble(*point, "x", source_, point_place);
      const double file_y = requireDouble(*point, "y", source_, point_place);
      curve.control_points.emplace_back(file_y, file_x);
    }
  }

  static bool isBarrier(const XMLElement& color_set) {
    const char* boundary = color_set.Attribute("boundary");
    return boundary && std::string(boundary) == io_detail::kBarrierBoundary;
  }

  double readPosition(const XMLElement& element, int segments, const std::string& place) const {
    const double global_id = requireDouble(element, "globalID", source_, place);
    const double s = global_id / io_detail::kGlobalIdPerSegment;
    if (s < 0.0 || s > segments) {
      throw FormatError(source_, place,
                        "globalID " + std::string(element.Attribute("globalID")) + " outside 0.." +
                            std::to_string(segments * 10) + " (10 per segment)");
    }
    return s;
  }

  std::vector<ColorPoint> readColors(const XMLElement& set, const char* name, int segments,
                                     const std::string& curve_place) const {
    std::vector<ColorPoint> colors;
    for (const XMLElement* c = set.FirstChildElement(name); c; c = c->NextSiblingElement(name)) {
      const std::string place = curve_place + " " + name + " " + std::to_string(colors.size());
      ColorPoint point;
      point.position = readPosition(*c, segments, place);
      const char* channels[3] = {"R", "G", "B"};
      for (int i = 0; i < 3; ++i) {
        // The file labels its channels B, G, R where we have R, G, B.
        const double value = requireDouble(*c, channels[2 - i], source_, place);
        if (value < 0.0 || value > io_detail::kColorScale) {
          throw FormatError(source_, place,
                            std::string("colour channel ") + channels[2 - i] + " outside 0..255");
        }
        point.rgb[i] = value / io_detail::kColorScale;
      }
      colors.push_back(point);
    }
    std::stable_sort(colors.begin(), colors.end(), [](const ColorPoint& a, const ColorPoint& b) {
      return a.position < b.position;
    });
    return colors;
  }

  std::vector<BlurPoint> readBlurPoints(const XMLElement& set, int segments,
                                        const std::string& curve_place) const {
    std::vector<BlurPoint> blur;
    for (const XMLElement* b = set.FirstChildElement("best_scale"); b;
         b = b->NextSiblingElement("best_scale")) {
      const std::string place = curve_place + " best_scale " + std::to_string(blur.size());
      BlurPoint point;
      point.position = readPosition(*b, segments, place);
      point.sigma = requireDouble(*b, "value", source_, place);
      if (point.sigma < 0.0) throw FormatError(source_, place, "negative blur value");
      blur.push_back(point);
    }
    std::stable_sort(blur.begin(), blur.end(), [](const BlurPoint& a, const BlurPoint& b) {
      return a.position < b.position;
    });
    return blur;
  }

  std::string source_;
  std::size_t total_points_ = 0;
};

}  // namespace

DiffusionCurveImage parseOrzanXml(const std::string& text) {
  return OrzanReader("<string>").read(text);
}

DiffusionCurveImage readOrzanXml(const std::string& path) {
  return OrzanReader(path).read(io_detail::readTextFile(path));
}

}  // namespace vicc_glyphs
