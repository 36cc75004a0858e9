#pragma once
// The basic SVG shapes (rect with optional rounded corners, circle, ellipse, polygon,
// polyline, line) as contours, by building the equivalent path.

#include <tinyxml2.h>

#include <string>
#include <vector>

#include "svg_geometry.hpp"

namespace vicc_glyphs {
namespace io_detail {

/// A length attribute: a number, optionally with the unit "px". Missing gives `fallback`;
/// anything else throws std::invalid_argument.
double svgLength(const tinyxml2::XMLElement& element, const char* name, double fallback);

/// Contours of a basic shape element (`path` is handled by the path data parser); an empty
/// result for zero-sized shapes, which SVG does not render.
std::vector<Contour> basicShapeContours(const tinyxml2::XMLElement& element, PointBudget& budget);
/// The same as subpaths as drawn (polyline and line stay open, for stroking).
std::vector<Subpath> basicShapeSubpaths(const tinyxml2::XMLElement& element, PointBudget& budget);

/// True for the element names basicShapeContours understands.
bool isBasicShape(const std::string& name);

}  // namespace io_detail
}  // namespace vicc_glyphs
