#include "vicc_glyphs/pacemod/polyline.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vicc_glyphs {
namespace pacemod {

Polyline sampleCurve(const DiffusionCurve& curve, int per_segment) {
  const int segments = curve.segmentCount();
  Polyline line;
  if (segments < 1) return line;
  per_segment = std::max(per_segment, 1);
  for (int i = 0; i < segments * per_segment; ++i) {
    line.push_back(curve.pointAt(static_cast<double>(i) / per_segment));
  }
  line.push_back(curve.pointAt(segments));
  return line;
}

double distanceToPolyline(const Point2& point, const Polyline& line) {
  if (line.empty()) return std::numeric_limits<double>::infinity();
  double best = (point - line.front()).squaredNorm();
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    const Point2 d = line[i + 1] - line[i];
    const double length2 = d.squaredNorm();
    const double t = length2 > 0.0 ? std::clamp((point - line[i]).dot(d) / length2, 0.0, 1.0) : 0.0;
    best = std::min(best, (point - line[i] - t * d).squaredNorm());
  }
  return std::sqrt(best);
}

double polylineArea(const Polyline& line) {
  double area = 0.0;
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    area += line[i].x() * line[i + 1].y() - line[i + 1].x() * line[i].y();
  }
  if (!line.empty())
    area += line.back().x() * line.front().y() - line.front().x() * line.back().y();
  return 0.5 * area;
}

bool insidePolygon(const Point2& point, const Polyline& line) {
  bool inside = false;
  for (std::size_t i = 0, j = line.size() - 1; i < line.size(); j = i++) {
    const Point2& a = line[i];
    const Point2& b = line[j];
    if ((a.y() > point.y()) != (b.y() > point.y()) &&
        point.x() < (b.x() - a.x()) * (point.y() - a.y()) / (b.y() - a.y()) + a.x()) {
      inside = !inside;
    }
  }
  return inside;
}

}  // namespace pacemod
}  // namespace vicc_glyphs
