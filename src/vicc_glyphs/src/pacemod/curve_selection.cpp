#include "vicc_glyphs/pacemod/curve_selection.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "vicc_glyphs/pacemod/polyline.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

int parseIndex(const std::string& item) {
  if (item.empty() || item.find_first_not_of("0123456789") != std::string::npos ||
      item.size() > 9) {
    throw std::invalid_argument("curve index '" + item + "' is not a non-negative integer");
  }
  return std::stoi(item);
}

}  // namespace

CurveSelection CurveSelection::parse(const std::string& text) {
  if (text == "all") return {Kind::All, {}};
  if (text == "outer") return {Kind::Outer, {}};
  CurveSelection selection{Kind::Indices, {}};
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) selection.indices.push_back(parseIndex(item));
  if (selection.indices.empty()) throw std::invalid_argument("empty curve list");
  // getline drops an empty last item: "0," would pass where ",0" does not.
  if (text.back() == ',') throw std::invalid_argument("curve list '" + text + "' ends with ','");
  return selection;
}

std::vector<int> selectCurves(const DiffusionCurveImage& image, const CurveSelection& selection) {
  const int count = static_cast<int>(image.curves.size());
  std::vector<int> result;
  if (selection.kind == CurveSelection::Kind::Indices) {
    for (int index : selection.indices) {
      if (index < 0 || index >= count) {
        throw std::invalid_argument("curve index " + std::to_string(index) +
                                    " out of range (image has " + std::to_string(count) +
                                    " curves)");
      }
      result.push_back(index);
    }
    std::sort(result.begin(), result.end());
    result.erase(std::unique(result.begin(), result.end()), result.end());
    return result;
  }
  std::vector<Polyline> lines;
  for (const DiffusionCurve& curve : image.curves) lines.push_back(sampleCurve(curve, 8));
  for (int i = 0; i < count; ++i) {
    bool enclosed = false;
    if (selection.kind == CurveSelection::Kind::Outer && !lines[i].empty()) {
      // A point in the middle of a segment, not a join shared with a touching contour.
      const Point2 probe = image.curves[i].pointAt(0.5);
      for (int j = 0; j < count && !enclosed; ++j) {
        enclosed = j != i && isClosedPolyline(lines[j]) && insidePolygon(probe, lines[j]);
      }
    }
    if (!enclosed) result.push_back(i);
  }
  return result;
}

}  // namespace pacemod
}  // namespace vicc_glyphs
