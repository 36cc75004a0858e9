#pragma once
// Independent geometry for checking importer results: dense flattening of curves and a
// winding-number point-in-polygon test.

#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"

namespace vicc_glyphs {
namespace test {

inline std::vector<Point2> flattenCurve(const DiffusionCurve& curve, int pieces_per_segment = 64) {
  std::vector<Point2> points;
  const int segments = curve.segmentCount();
  for (int i = 0; i <= segments * pieces_per_segment; ++i) {
    points.push_back(curve.pointAt(static_cast<double>(i) / pieces_per_segment));
  }
  return points;
}

inline int winding(const std::vector<std::vector<Point2>>& polygons, const Point2& p) {
  int w = 0;
  for (const auto& poly : polygons) {
    for (std::size_t i = 0; i + 1 < poly.size(); ++i) {
      const Point2 a = poly[i], b = poly[i + 1];
      const double cross = (b.x() - a.x()) * (p.y() - a.y()) - (p.x() - a.x()) * (b.y() - a.y());
      if (a.y() <= p.y() && b.y() > p.y() && cross > 0) ++w;
      if (b.y() <= p.y() && a.y() > p.y() && cross < 0) --w;
    }
  }
  return w;
}

inline std::vector<std::vector<Point2>> flattenAll(const DiffusionCurveImage& image) {
  std::vector<std::vector<Point2>> polygons;
  for (const DiffusionCurve& c : image.curves) polygons.push_back(flattenCurve(c));
  return polygons;
}

/// Point at parameter s moved `distance` along the unit left normal (negative: right).
inline Point2 besideCurve(const DiffusionCurve& curve, double s, double distance) {
  const Point2 d = curve.derivativeAt(s).normalized();
  return curve.pointAt(s) + distance * Point2(d.y(), -d.x());
}

}  // namespace test
}  // namespace vicc_glyphs
