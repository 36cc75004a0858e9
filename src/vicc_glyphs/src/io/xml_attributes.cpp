#include "xml_attributes.hpp"

#include <algorithm>
#include <cmath>

#include "vicc_glyphs/io/format_error.hpp"

namespace vicc_glyphs {
namespace io_detail {
namespace {

std::string where(const tinyxml2::XMLElement& element, const std::string& place) {
  return place + " (<" + element.Name() + "> line " + std::to_string(element.GetLineNum()) + ")";
}

}  // namespace

void parseXmlDocument(tinyxml2::XMLDocument& document, const std::string& text,
                      const std::string& source) {
  if (document.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS) {
    const char* reason = document.ErrorStr();
    throw FormatError(source, "line " + std::to_string(document.ErrorLineNum()),
                      std::string("malformed XML: ") + (reason ? reason : "unknown error"));
  }
}

std::size_t countOccurrences(const std::string& text, const std::string& needle) {
  std::size_t count = 0;
  for (std::size_t at = text.find(needle); at != std::string::npos;
       at = text.find(needle, at + needle.size())) {
    ++count;
  }
  return count;
}

double requireDouble(const tinyxml2::XMLElement& element, const char* name,
                     const std::string& source, const std::string& place) {
  if (!element.Attribute(name)) {
    throw FormatError(source, where(element, place), std::string("missing attribute ") + name);
  }
  double value = 0.0;
  if (element.QueryDoubleAttribute(name, &value) != tinyxml2::XML_SUCCESS ||
      !std::isfinite(value)) {
    throw FormatError(source, where(element, place),
                      std::string("attribute ") + name + "=\"" + element.Attribute(name) +
                          "\" is not a finite number");
  }
  return value;
}

int requireInt(const tinyxml2::XMLElement& element, const char* name, const std::string& source,
               const std::string& place) {
  if (!element.Attribute(name)) {
    throw FormatError(source, where(element, place), std::string("missing attribute ") + name);
  }
  int value = 0;
  if (element.QueryIntAttribute(name, &value) != tinyxml2::XML_SUCCESS) {
    throw FormatError(source, where(element, place),
                      std::string("attribute ") + name + "=\"" + element.Attribute(name) +
                          "\" is not an integer");
  }
  return value;
}

std::string tooManyControlPointsMessage() {
  return "more than " + std::to_string(kMaxControlPointsPerFile) +
         " control points (limit per file)";
}

void rejectTooManyControlPoints(const std::string& text, const std::string& source) {
  if (countOccurrences(text, "<control_point ") > kMaxControlPointsPerFile) {
    throw FormatError(source, "", tooManyControlPointsMessage());
  }
}

const tinyxml2::XMLElement& parseCurveFileRoot(tinyxml2::XMLDocument& document,
                                               const std::string& text, const std::string& source,
                                               const char* root_name, const std::string& expected) {
  rejectTooManyControlPoints(text, source);
  parseXmlDocument(document, text, source);
  const tinyxml2::XMLElement* root = document.RootElement();
  if (!root || std::string(root->Name()) != root_name) {
    throw FormatError(source, "root", "expected " + expected);
  }
  return *root;
}

const tinyxml2::XMLElement& requireChild(const tinyxml2::XMLElement& parent, const char* name,
                                         const std::string& source, const std::string& place) {
  const tinyxml2::XMLElement* child = parent.FirstChildElement(name);
  if (!child) throw FormatError(source, place, std::string("missing <") + name + ">");
  return *child;
}

int requireDrawableSegments(const DiffusionCurve& curve, const std::string& source,
                            const std::string& place) {
  const int segments = curve.segmentCount();
  if (segments == 0) {
    throw FormatError(source, place,
                      std::to_string(curve.control_points.size()) +
                          " control points; a curve needs 3K+1 with K >= 1");
  }
  const bool zero_length =
      std::all_of(curve.control_points.begin(), curve.control_points.end(),
                  [&](const Point2& p) { return p == curve.control_points.front(); });
  if (zero_length) throw FormatError(source, place, "zero-length curve (all points equal)");
  return segments;
}

void requireImageSize(const tinyxml2::XMLElement& root, const std::string& source,
                      const std::string& place, int& width, int& height) {
  constexpr int kMaxImageSide = 100000;
  width = requireInt(root, "image_width", source, place);
  height = requireInt(root, "image_height", source, place);
  if (width <= 0 || height <= 0 || width > kMaxImageSide || height > kMaxImageSide) {
    throw FormatError(source, place,
                      "image size " + std::to_string(width) + "x" + std::to_string(height) +
                          " outside 1.." + std::to_string(kMaxImageSide));
  }
}

}  // namespace io_detail
}  // namespace vicc_glyphs
