#pragma once
// The sharp corners of an icon contour and its offset there (PACEMOD waves are offsets of the
// contour by a signed amount w that varies along it). Away from corners the offset point is
// k + w n. At a corner two cases differ:
// - outside the angle the offset contour is a circular arc around the corner: the corner's
//   offset point is corner + |w| along the bisector of both sides' normals;
// - inside the angle the offsets of both sides overlap (a swallowtail): the offset contour is
//   the two offset lines up to their meeting point on the bisector, corner + w / cos(turn / 2)
//   (the miter), and the offset points of either side past the bisector do not belong to it.

#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "vicc_glyphs/bspline/arc_length.hpp"
#include "vicc_glyphs/bspline/bspline_curve.hpp"

namespace vicc_glyphs {
namespace pacemod {

/// Joins turning by less than this (degrees) are smooth (the B-spline conversion makes them C1).
constexpr double kSmoothJoinDegrees = 3.5;
/// Corners closer than this (px of arc length: a sub-pixel step or tooth of the imported
/// polygon, invisible at the rendered size) are one corner that turns by both, or none if their
/// turns cancel.
constexpr double kOneCornerPx = 0.5;

/// Inside an angle sharper than this the miter is capped at this length (turns above 165
/// degrees: spikes thinner than 15 degrees); there the corner point stays nearer than w.
constexpr double kMaxMiterLength = 8.0;

/// A sharp corner of a closed contour: a C0 join (the B-spline conversion keeps joins turning
/// by more than 3.5 degrees as triple knots), or the closing point where the end tangents
/// differ by as much.
struct ContourCorner {
  double arc_length = 0.0;
  Point2 point = Point2::Zero();
  Point2 tangent_before = Point2::Zero();  ///< unit tangent (direction of travel) before it
  Point2 tangent_after = Point2::Zero();   ///< unit tangent after it
  Point2 normal_before = Point2::Zero();   ///< outward unit normal of the side ending here
  Point2 normal_after = Point2::Zero();    ///< outward unit normal of the side starting here
  Point2 bisector = Point2::Zero();        ///< outward unit bisector of the two normals
  double half_turn_cosine = 1.0;           ///< cos(turn / 2) = <bisector, normal_before>
  /// Sum of the unit tangents of both sides: across the bisector line, along the way.
  Point2 forward = Point2::Zero();
  /// +1 when outward offsets (w > 0) lie inside the angle (a concave corner), -1 when inward
  /// ones do (a convex corner).
  int inner_sign = 1;

  /// True when the offset w lies inside the angle (the swallowtail side).
  bool inside(double w) const { return w * inner_sign > 0.0; }
  /// Distance from the corner per unit of w along the bisector: 1 outside the angle, the
  /// miter length 1 / cos(turn / 2) (capped at kMaxMiterLength) inside.
  double stretch(double w) const;
  /// The corner's point of the contour offset by w.
  Point2 offsetPoint(double w) const { return point + w * stretch(w) * bisector; }
  /// Arc length to either side within which offset points of the sides (by w) lie past the
  /// bisector: |w| tan(turn / 2) inside the angle, 0 outside.
  double swallowtail(double w) const;
  /// The offset inside the angle whose offset points at arc distance `d` from the corner (on
  /// either side) lie on the bisector: d / tan(turn / 2), not capped like the miter.
  double bisectorOffsetAt(double d) const;
  /// True when `q`, an offset point of the side before (`side` = -1) or after (+1) the corner,
  /// lies past the bisector on the other side's half.
  bool pastBisector(const Point2& q, int side) const {
    return -side * (q - point).dot(forward) > 0.0;
  }
};

/// The corners of a closed contour (clamped cubic B-spline, first == last point) by increasing
/// arc length, the closing point (if a corner) first at 0; `area` is its signed area (the
/// orientation of the normals: positive = clockwise on screen).
std::vector<ContourCorner> contourCorners(const bspline::BSplineCurve& contour,
                                          const bspline::ArcLengthTable& table, double area);

/// An upper bound of ContourCorner::swallowtail(w) for every corner (the miter cap bounds
/// tan(turn / 2)).
inline double maxSwallowtail(double w) { return kMaxMiterLength * std::abs(w); }

/// Index ranges [first, second), in increasing order and disjoint, that forEachCornerNear visits.
std::array<std::pair<int, int>, 3> cornerIndexRangesNear(const std::vector<ContourCorner>& corners,
                                                         double l, double reach, double length);

/// Calls visit(index), by increasing index, for every corner of `corners` (contourCorners' order,
/// arc lengths in [0, length)) whose cyclic arc-length distance to `l` is at most `reach`, and for
/// a few that lie a hair farther: callers apply their own exact test. Knot points and fit samples
/// look only at the corners near them this way, not at all of a contour's corners (an icon with
/// dozens of corners and thousands of knot points spent millions of instructions on the others).
template <class Visit>
void forEachCornerNear(const std::vector<ContourCorner>& corners, double l, double reach,
                       double length, Visit&& visit) {
  for (const auto& range : cornerIndexRangesNear(corners, l, reach, length)) {
    for (int c = range.first; c < range.second; ++c) visit(c);
  }
}

/// Per arc length l of `arc_lengths` (fastest by increasing l) the corner of `corners` (distinct
/// arc lengths by increasing index, as contourCorners gives them) nearest to it by
/// |l - arc length|, the closing corner (at 0) counted at `length` when l lies past the middle;
/// the lowest index among equally near ones; -1 without corners.
std::vector<int> nearestCorners(const std::vector<ContourCorner>& corners,
                                const std::vector<double>& arc_lengths, double length);

/// Outward unit normal for the tangent `d` of a contour with signed area `area`.
Point2 outwardNormalOf(const Point2& d, double area);

/// cos(kSmoothJoinDegrees): unit tangents with a larger dot product meet in a smooth join.
double smoothJoinCosine();

/// Unit direction of a control polygon at points[from], in the direction of travel: towards
/// the first of the next `max_steps` points that differs from it (`step` +1), or from the first
/// such point before it (-1), so that zero-length handles are skipped; zero if there is none.
Point2 controlPolygonDirection(const std::vector<Point2>& points, int from, int step,
                               int max_steps);

}  // namespace pacemod
}  // namespace vicc_glyphs
