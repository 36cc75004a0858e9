#pragma once
// Paint servers (gradients, patterns) are not represented; lenient imports replace a gradient
// by the mean colour of its stops, so the shape keeps roughly its colour.

#include <tinyxml2.h>

#include <functional>
#include <optional>
#include <string>

#include "vicc_glyphs/dci/diffusion_curve.hpp"

namespace vicc_glyphs {
namespace io_detail {

/// Mean stop-color of a <linearGradient> or <radialGradient> (stops inherited through href);
/// nullopt for other elements or gradients without stops. `lookup` resolves ids.
std::optional<Color> gradientMeanColor(
    const tinyxml2::XMLElement& server,
    const std::function<const tinyxml2::XMLElement*(const std::string&)>& lookup);

}  // namespace io_detail
}  // namespace vicc_glyphs
