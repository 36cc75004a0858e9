#pragma once
// SVG transform lists: matrix, translate, scale, rotate (with optional centre), skewX, skewY.

#include <Eigen/Geometry>
#include <string>

namespace vicc_glyphs {
namespace io_detail {

using Affine2 = Eigen::Transform<double, 2, Eigen::Affine>;

/// Parses a transform attribute (applied right to left to points, as in SVG). Throws
/// std::invalid_argument with a reason on syntax errors or non-invertible results.
Affine2 parseSvgTransform(const std::string& text);

}  // namespace io_detail
}  // namespace vicc_glyphs
