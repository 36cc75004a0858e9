#pragma once
// Polylines of diffusion curves, for the distance field, the amplitude measurement and the
// intersection checks.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"

namespace vicc_glyphs {
namespace pacemod {

using Polyline = std::vector<Point2>;

/// `per_segment` (>= 1) equal parameter steps per Bezier segment, plus the end point.
Polyline sampleCurve(const DiffusionCurve& curve, int per_segment = 16);

/// Euclidean distance from `point` to the nearest point of `line` (+inf for an empty line).
double distanceToPolyline(const Point2& point, const Polyline& line);

/// Nearest points of a set of polylines for many queries: their segments in grid cells of
/// `cell` pixels (coarser when that would take over 4 M cells), each query searching rings of
/// cells outward until no nearer segment can be left, or none nearer than a given radius.
/// Throws std::invalid_argument for a cell that is not a finite number > 0. The polylines must
/// outlive it.
class PolylineSetDistance {
 public:
  struct Segment {
    int line = -1;  ///< index into the polylines; -1: none
    int segment = -1;
  };

  explicit PolylineSetDistance(std::vector<const Polyline*> lines, double cell = 4.0);

  /// Whether no polyline has a segment with finite ends (every query then finds none).
  bool empty() const { return entries_.empty(); }
  /// The segment nearest to `point` among those nearer than `radius` (ties: the first in the
  /// order of lines and segments within a cell); none for a non-finite point.
  Segment nearestSegment(const Point2& point,
                         double radius = std::numeric_limits<double>::infinity()) const;
  /// The point of `segment` nearest to `point` (a vertex exactly when it is one).
  Point2 nearestOn(const Segment& segment, const Point2& point) const;

 private:
  /// Every segment tried: for a query too far away for cell indices.
  Segment nearestScanned(const Point2& point, double radius) const;

  /// A segment in a cell, with its end points (no lookup through the polylines per test).
  struct Entry {
    Point2 a, b;
    Segment segment;
  };

  static constexpr double kMaxCells = 1 << 22;
  static constexpr double kFarCells = 1e15;
  std::vector<const Polyline*> lines_;
  double cell_;
  long long min_x_ = 0, min_y_ = 0, max_x_ = 0, max_y_ = 0;  ///< the cells the segments touch
  std::vector<int> start_;      ///< per cell (row-major) its first entry in entries_, + end
  std::vector<Entry> entries_;  ///< cell by cell
};

/// distanceToPolyline for many points against one polyline (a PolylineSetDistance of one line).
/// `line` must outlive it.
class PolylineDistance {
 public:
  explicit PolylineDistance(const Polyline& line, double cell = 4.0);
  double operator()(const Point2& point) const;
  /// The nearest point of the polyline (NaN for an empty line or a non-finite query; a vertex
  /// exactly when it is one) and, if asked, the index of the segment it lies on (-1 for none).
  Point2 nearest(const Point2& point, int* segment = nullptr) const;

 private:
  const Polyline& line_;
  PolylineSetDistance segments_;
};

/// Shoelace area of a closed polyline (positive: clockwise on screen, y down).
double polylineArea(const Polyline& line);

/// True when `line` is a closed polygon: it ends where it starts and has at least 5 points (a
/// sampled curve of at least one segment).
bool isClosedPolyline(const Polyline& line);

/// Arc-length offset from `from` to `to` on a closed contour of the given length, the shorter way
/// round: in [-length / 2, length / 2] (a point just past the closing point at 0 and L is near).
double cyclicOffset(double from, double to, double length);

/// The arc-length distance of two points of a closed contour: |cyclicOffset|.
double cyclicDistance(double a, double b, double length);

/// For `items` sorted by arc length (`arc_length(item)`, in [0, length]) along a closed contour:
/// index ranges [first, second), in increasing order and disjoint, holding every item whose
/// cyclic arc-length distance to `l` is at most `reach`, and a few that lie a hair farther
/// (against round-off): callers apply their own exact test. All of them when the reach is half
/// the length or more (or NaN). A binary search instead of a test of every item: icon corners
/// near a knot point, knot points near a crossing.
template <class Items, class ArcLength>
std::array<std::pair<int, int>, 3> indexRangesNear(const Items& items, double l, double reach,
                                                   double length, ArcLength&& arc_length) {
  const int count = static_cast<int>(items.size());
  std::array<std::pair<int, int>, 3> ranges{};
  const double r = reach + 1e-9 * (std::abs(reach) + std::abs(l) + length) + 1e-12;
  if (!(r < 0.5 * length)) {  // also for NaN
    ranges[0] = {0, count};
    return ranges;
  }
  const auto first_at_or_above = [&](double a) {
    return static_cast<int>(
        std::partition_point(items.begin(), items.end(),
                             [&](const auto& item) { return arc_length(item) < a; }) -
        items.begin());
  };
  const auto first_above = [&](double a) {
    return static_cast<int>(
        std::partition_point(items.begin(), items.end(),
                             [&](const auto& item) { return !(a < arc_length(item)); }) -
        items.begin());
  };
  const double low = l - r, high = l + r;
  // Past `length` the window continues at 0, before 0 at `length`.
  if (high >= length) ranges[0] = {0, first_above(high - length)};
  ranges[1] = {std::max(ranges[0].second, first_at_or_above(low)), first_above(high)};
  if (low <= 0.0) ranges[2] = {std::max(ranges[1].second, first_at_or_above(low + length)), count};
  ranges[1].second = std::max(ranges[1].first, ranges[1].second);
  return ranges;
}

/// True when `point` lies inside the closed polygon `line` (even-odd rule).
bool insidePolygon(const Point2& point, const Polyline& line);

}  // namespace pacemod
}  // namespace vicc_glyphs
