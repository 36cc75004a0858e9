#include "fill_regions.hpp"

#include <algorithm>
#include <cmath>

namespace vicc_glyphs {
namespace io_detail {
namespace {

// Pieces per Bezier: enough for the control polygon's bend, even so the midpoint is a vertex.
int piecesFor(const Point2* b) {
  const Point2 chord = b[3] - b[0];
  const double chord_length = chord.norm();
  double bend = 0.0;
  for (int i = 1; i <= 2; ++i) {
    const Point2 d = b[i] - b[0];
    bend = std::max(bend, chord_length > 0.0
                              ? std::abs(chord.x() * d.y() - chord.y() * d.x()) / chord_length
                              : d.norm());
  }
  // Clamped as a double first: huge or non-finite coordinates must not overflow the int.
  const double wanted = std::ceil(std::sqrt(bend * 8.0));
  const int pieces =
      wanted >= 1.0 && wanted <= 32.0 ? static_cast<int>(wanted) : (wanted > 1.0 ? 32 : 1);
  return 2 * std::clamp((pieces + 1) / 2, 1, 16);
}

Point2 bezier(const Point2* b, double t) {
  const double u = 1.0 - t;
  return u * u * u * b[0] + 3.0 * u * u * t * b[1] + 3.0 * u * t * t * b[2] + t * t * t * b[3];
}

}  // namespace

FlatContour flatten(const Contour& contour) {
  FlatContour flat;
  flat.points.push_back(contour.front());
  for (std::size_t k = 0; k + 3 < contour.size(); k += 3) {
    const Point2* b = &contour[k];
    const int pieces = piecesFor(b);
    for (int i = 1; i <= pieces; ++i)
      flat.points.push_back(bezier(b, static_cast<double>(i) / pieces));
  }
  for (const Point2& p : flat.points) flat.box.extend(p);
  return flat;
}

int windingNumber(const std::vector<FlatContour>& contours, const Point2& p) {
  int winding = 0;
  for (const FlatContour& c : contours) {
    if (p.y() < c.box.min().y() || p.y() > c.box.max().y() || p.x() > c.box.max().x()) continue;
    for (std::size_t i = 0; i + 1 < c.points.size(); ++i) {
      const Point2& a = c.points[i];
      const Point2& b = c.points[i + 1];
      // Count signed crossings of the ray to +x; half-open in y so vertices count once.
      const double side = (b.x() - a.x()) * (p.y() - a.y()) - (p.x() - a.x()) * (b.y() - a.y());
      if (a.y() <= p.y() && b.y() > p.y() && side > 0.0) ++winding;
      if (b.y() <= p.y() && a.y() > p.y() && side < 0.0) --winding;
    }
  }
  return winding;
}

bool FilledShape::contains(const Point2& p) const {
  const int winding = windingNumber(flat, p);
  return rule == FillRule::kNonZero ? winding != 0 : (winding % 2) != 0;
}

void PaintedScene::addShape(std::vector<Contour> contours, const Color& fill, FillRule rule) {
  FilledShape shape;
  shape.contours = std::move(contours);
  for (const Contour& c : shape.contours) shape.flat.push_back(flatten(c));
  shape.fill = fill;
  shape.rule = rule;
  shapes_.push_back(std::move(shape));
}

Color PaintedScene::colorAt(const Point2& p) const {
  for (auto it = shapes_.rbegin(); it != shapes_.rend(); ++it) {
    if (it->contains(p)) return it->fill;
  }
  return background_;
}

}  // namespace io_detail
}  // namespace vicc_glyphs
