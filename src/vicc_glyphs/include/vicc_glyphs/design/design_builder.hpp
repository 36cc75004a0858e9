#pragma once
// Builds the diffusion curve image of a design for given data levels: loads the icon (SVG or
// Orzan XML; no raster import, so no GPL code), then applies the encodings with PACEMOD in a
// fixed order: fill colour, glyph scale, inflate, waves, dashes, hidden curves.

#include <map>
#include <string>
#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"
#include "vicc_glyphs/design/glyph_design.hpp"

namespace vicc_glyphs::design {

/// The design's icon at `size_px` width (0: the design's size_px); an SVG icon has one curve per
/// region boundary (the SVG import's rule), so curve numbers name icon parts. Throws FormatError.
DiffusionCurveImage loadIcon(const GlyphDesign& design, int size_px);

/// The modified image for `levels` (one per variable, as GlyphDesign::levelsFor returns).
/// Throws DesignValueError for a level out of range; PACEMOD errors pass through as
/// std::invalid_argument.
DiffusionCurveImage buildGlyph(const GlyphDesign& design, const std::vector<int>& levels,
                               const perception::PerceptionModel& model, int size_px = 0);

/// The same on `icon`, the design's icon as loadIcon returns it: a caller that builds many
/// glyphs of one design (the glyph server, the map) imports it once instead of for every glyph.
DiffusionCurveImage buildGlyph(const GlyphDesign& design, const std::vector<int>& levels,
                               const perception::PerceptionModel& model, DiffusionCurveImage icon);

}  // namespace vicc_glyphs::design
