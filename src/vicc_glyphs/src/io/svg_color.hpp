#pragma once
// SVG paint values: #rgb, #rrggbb, rgb(r, g, b) with numbers or percentages, and the basic
// named colours (HTML 4 set plus orange and grey spellings).

#include <optional>
#include <string>

#include "vicc_glyphs/dci/diffusion_curve.hpp"

namespace vicc_glyphs {
namespace io_detail {

/// Parses a paint value. Returns std::nullopt for "none"; throws std::invalid_argument with a
/// reason for anything it does not understand (gradients, unknown names, bad syntax).
std::optional<Color> parseSvgPaint(const std::string& value);

}  // namespace io_detail
}  // namespace vicc_glyphs
