#pragma once
// The SVG path data mini-language (the `d` attribute): M L H V C S Q T A Z in absolute and
// relative forms, turned into closed cubic Bezier contours (quadratics are elevated exactly,
// arcs approximated, lines become straight cubics).

#include <string>
#include <vector>

#include "svg_geometry.hpp"

namespace vicc_glyphs {
namespace io_detail {

/// Parses `d`. Throws std::invalid_argument ("unknown path command 'X' at offset N", ...) on
/// syntax errors and std::length_error when the point budget is exceeded.
std::vector<Contour> parseSvgPathData(const std::string& d, PointBudget& budget);
/// Parses `d` into subpaths as drawn (open ones stay open, for stroking).
std::vector<Subpath> parseSvgPathSubpaths(const std::string& d, PointBudget& budget);

}  // namespace io_detail
}  // namespace vicc_glyphs
