#pragma once
// Polylines of diffusion curves, for the distance field, the amplitude measurement and the
// intersection checks.

#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"

namespace vicc_glyphs {
namespace pacemod {

using Polyline = std::vector<Point2>;

/// `per_segment` (>= 1) equal parameter steps per Bezier segment, plus the end point.
Polyline sampleCurve(const DiffusionCurve& curve, int per_segment = 16);

/// Euclidean distance from `point` to the nearest point of `line` (+inf for an empty line).
double distanceToPolyline(const Point2& point, const Polyline& line);

/// distanceToPolyline for many points against one polyline: its segments in grid cells of
/// `cell` pixels (coarser when that would take over 4 M cells), each query searching rings of
/// cells outward until no nearer segment can be left. Throws std::invalid_argument for a cell
/// that is not a finite number > 0. `line` must outlive it.
class PolylineDistance {
 public:
  explicit PolylineDistance(const Polyline& line, double cell = 4.0);
  double operator()(const Point2& point) const;
  /// The nearest point of the polyline (NaN for an empty line or a non-finite query; a vertex
  /// exactly when it is one) and, if asked, the index of the segment it lies on (-1 for none).
  Point2 nearest(const Point2& point, int* segment = nullptr) const;

 private:
  int nearestSegment(const Point2& point) const;  ///< -1 when there is none
  /// Every segment tried: for a query too far away for cell indices.
  int nearestSegmentScanned(const Point2& point) const;

  static constexpr double kMaxCells = 1 << 22;
  static constexpr double kFarCells = 1e15;
  const Polyline& line_;
  double cell_;
  long long min_x_ = 0, min_y_ = 0, max_x_ = 0, max_y_ = 0;  ///< the cells the segments touch
  std::vector<int> start_;     ///< per cell (row-major) its first entry in segments_, + end
  std::vector<int> segments_;  ///< segment indices, cell by cell
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

/// True when `point` lies inside the closed polygon `line` (even-odd rule).
bool insidePolygon(const Point2& point, const Polyline& line);

}  // namespace pacemod
}  // namespace vicc_glyphs
