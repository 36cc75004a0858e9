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

}  // namespace io_detail
}  // namespace vicc_glyphs
