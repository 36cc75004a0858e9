#pragma once
// Conversion of SVG elliptical arcs (endpoint parameterisation, SVG 1.1 appendix F.6) into
// cubic Beziers of at most 90 degrees each.

#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"

namespace vicc_glyphs {
namespace io_detail {

/// Control points c1, c2, end for each cubic approximating the arc from `from` to `to`
/// (3 points per cubic). Radii are corrected as the SVG rules say; zero radii give a line.
std::vector<Point2> arcToCubics(const Point2& from, double rx, double ry, double x_axis_degrees,
                                bool large_arc, bool sweep, const Point2& to);

/// The arc of the ellipse with radii rx, ry (its x axis turned by `rotation_radians`) around
/// `centre` from angle `theta` turning by `delta` radians, as cubics of at most 90 degrees
/// (c1, c2, end per cubic); the first starts at `from`, the last ends exactly at `to`.
std::vector<Point2> centredArcToCubics(const Point2& centre, double rx, double ry,
                                       double rotation_radians, double theta, double delta,
                                       const Point2& from, const Point2& to);

}  // namespace io_detail
}  // namespace vicc_glyphs
