#pragma once
// Cubic Bezier fitting of polylines (Schneider, "An algorithm for automatically fitting
// digitized curves", Graphics Gems 1990): least squares with fixed end tangents, Newton
// reparameterisation, split at the worst point until within tolerance. The importer's region
// boundaries are flattened polygons; refitting gives curves with a few segments instead of one
// straight segment per polygon edge.

#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"

namespace vicc_glyphs {
namespace io_detail {

/// Appends the fit of the open polyline `points` (at least 2) to `control_points` (3K
/// points; the caller supplies the first point). `start_tangent` is the unit direction
/// leaving the first point, `end_tangent` the unit direction from the last point back into
/// the curve. Every point lies within `tolerance` of the result. Returns the segment count K.
int fitCubics(const std::vector<Point2>& points, const Point2& start_tangent,
              const Point2& end_tangent, double tolerance, std::vector<Point2>& control_points);

}  // namespace io_detail
}  // namespace vicc_glyphs
