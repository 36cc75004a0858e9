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

/// Shoelace area of a closed polyline (positive: clockwise on screen, y down).
double polylineArea(const Polyline& line);

/// True when `point` lies inside the closed polygon `line` (even-odd rule).
bool insidePolygon(const Point2& point, const Polyline& line);

}  // namespace pacemod
}  // namespace vicc_glyphs
