#include "vicc_glyphs/pacemod/contour_corners.hpp"

#include <algorithm>
#include <cmath>

#include "vicc_glyphs/pacemod/polyline.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

const double kSmoothCosine = smoothJoinCosine();

// Unit tangent (in the direction of travel) of the side after (`step` +1) or before (-1) the
// de Boor point `from` of a clamped cubic that passes through it (a C0 corner).
Point2 polygonDirection(const std::vector<Point2>& points, int from, int step) {
  return controlPolygonDirection(points, from, step, static_cast<int>(points.size()));
}

ContourCorner cornerOf(double arc_length, const Point2& point, const Point2& before,
                       const Point2& after, double area) {
  ContourCorner corner;
  corner.arc_length = arc_length;
  corner.point = point;
  corner.tangent_before = before;
  corner.tangent_after = after;
  corner.normal_before = outwardNormalOf(before, area);
  corner.normal_after = outwardNormalOf(after, area);
  corner.forward = before + after;
  const Point2 sum = corner.normal_before + corner.normal_after;
  // A cusp (a turn of 180 degrees, a spike's tip) has no bisector of the normals: straight on
  // past the tip is outward.
  corner.bisector = sum.norm() > 1e-9 ? Point2(sum.normalized()) : Point2(before);
  corner.half_turn_cosine = std::max(0.0, corner.bisector.dot(corner.normal_before));
  corner.inner_sign = corner.normal_before.dot(after) > 0.0 ? 1 : -1;
  return corner;
}

double halfTurnSine(double half_turn_cosine) {
  return std::sqrt(std::max(0.0, 1.0 - half_turn_cosine * half_turn_cosine));
}

}  // namespace

double ContourCorner::stretch(double w) const {
  if (!inside(w)) return 1.0;
  return std::min(kMaxMiterLength, 1.0 / std::max(half_turn_cosine, 1e-12));
}

double ContourCorner::swallowtail(double w) const {
  if (!inside(w)) return 0.0;
  return std::abs(w) * std::min(kMaxMiterLength,
                                halfTurnSine(half_turn_cosine) / std::max(half_turn_cosine, 1e-12));
}

double ContourCorner::bisectorOffsetAt(double d) const {
  const double sine = halfTurnSine(half_turn_cosine);
  return sine > 0.0 ? d * half_turn_cosine / sine : d;
}

std::array<std::pair<int, int>, 3> cornerIndexRangesNear(const std::vector<ContourCorner>& corners,
                                                         double l, double reach, double length) {
  return indexRangesNear(corners, l, reach, length,
                         [](const ContourCorner& corner) { return corner.arc_length; });
}

std::vector<int> nearestCorners(const std::vector<ContourCorner>& corners,
                                const std::vector<double>& arc_lengths, double length) {
  std::vector<int> nearest(arc_lengths.size(), -1);
  const int count = static_cast<int>(corners.size());
  int above = 0;  // the first corner at or above l: by increasing l it only moves forward
  for (std::size_t i = 0; i < arc_lengths.size() && count > 0; ++i) {
    const double l = arc_lengths[i];
    if (i > 0 && l < arc_lengths[i - 1]) above = 0;
    while (above < count && corners[above].arc_length < l) ++above;
    const bool closing_at_end = corners.front().arc_length == 0.0 && l > 0.5 * length;
    // The nearest is that one or the one before it; or the closing corner counted at `length`.
    // Ties go to the lowest index, as in a scan of all.
    int best = -1;
    double best_distance = 0.0;
    for (int c : {closing_at_end ? 0 : -1, above - 1, above}) {
      if (c < 0 || c >= count || c == best) continue;
      const double d = std::abs(l - (c == 0 && closing_at_end ? length : corners[c].arc_length));
      if (best < 0 || d < best_distance) {
        best = c;
        best_distance = d;
      }
    }
    nearest[i] = best;
  }
  return nearest;
}

Point2 outwardNormalOf(const Point2& d, double area) {
  const Point2 left = Point2(d.y(), -d.x()).normalized();
  return area > 0.0 ? left : Point2(-left);
}

double smoothJoinCosine() { return std::cos(kSmoothJoinDegrees * M_PI / 180.0); }

Point2 controlPolygonDirection(const std::vector<Point2>& points, int from, int step,
                               int max_steps) {
  const int size = static_cast<int>(points.size());
  for (int k = 1, q = from + step; k <= max_steps && q >= 0 && q < size; ++k, q += step) {
    const Point2 d = step * (points[q] - points[from]);
    if (d.norm() > 1e-9) return d.normalized();
  }
  return Point2::Zero();
}

std::vector<ContourCorner> contourCorners(const bspline::BSplineCurve& contour,
                                          const bspline::ArcLengthTable& table, double area) {
  std::vector<ContourCorner> corners;
  const std::vector<Point2>& points = contour.controlPoints();
  const int last = static_cast<int>(points.size()) - 1;
  const Point2 end_in = polygonDirection(points, last, -1);
  const Point2 start_out = polygonDirection(points, 0, 1);
  if (end_in.norm() > 0.0 && start_out.norm() > 0.0 && end_in.dot(start_out) < kSmoothCosine) {
    corners.push_back(cornerOf(0.0, points.front(), end_in, start_out, area));
  }
  for (double b : contour.breakpoints()) {
    if (b <= contour.domainBegin() || b >= contour.domainEnd() ||
        contour.multiplicity(b) < contour.degree()) {
      continue;
    }
    // The de Boor point the curve passes through at a knot of multiplicity >= 3.
    const auto first = std::lower_bound(contour.knots().begin(), contour.knots().end(), b);
    const int c = static_cast<int>(first - contour.knots().begin()) - 1;
    const Point2 in = polygonDirection(points, c, -1), out = polygonDirection(points, c, 1);
    if (!(in.norm() > 0.0 && out.norm() > 0.0)) continue;
    const double l = table.lengthAt(b);
    if (!corners.empty() && l - corners.back().arc_length < kOneCornerPx) {
      const ContourCorner& previous = corners.back();
      corners.back() =
          cornerOf(previous.arc_length, previous.point, previous.tangent_before, out, area);
    } else if (in.dot(out) < kSmoothCosine) {
      corners.push_back(cornerOf(l, points[c], in, out, area));
    }
  }
  // Merged corners that turn back by less than a smooth join are none.
  corners.erase(std::remove_if(corners.begin(), corners.end(),
                               [](const ContourCorner& c) {
                                 return c.tangent_before.dot(c.tangent_after) > kSmoothCosine;
                               }),
                corners.end());
  return corners;
}

}  // namespace pacemod
}  // namespace vicc_glyphs
