#pragma once
// The gradient glyph's structures (thesis 6.2.5.2, Fig. 6.18A), built from distance-field
// isolines of a closed contour (pacemod::offsetIsoline):
// - a band along the contour, separated from the rest of the glyph by a new curve at
//   band_mm inside; the band's colour is the glyph's inner colour with its HSV value and
//   saturation scaled (darker and more saturated: more contrast outward, for a growing value;
//   brighter: a shrinking one);
// - a central region, bounded by a new curve at inset_mm inside whose inner side is dashed in
//   a sign colour (PACEMOD colour modification with its inner diffusion barrier).

#include "vicc_glyphs/dci/diffusion_curve.hpp"

namespace vicc_glyphs::design {

/// The side of a closed curve that faces the region it encloses: true = left.
bool enclosedSideIsLeft(const DiffusionCurve& curve);

/// Adds the band curve inside closed curve `index` and recolours the band. Factors of 1 and 1
/// leave the image unchanged. Throws std::invalid_argument if the band leaves no region.
void addContourBand(DiffusionCurveImage& image, int index, double band_mm, double value_factor,
                    double saturation_factor, double glyph_size_mm);

/// Adds the central-region curve inset_mm inside closed curve `index` (both sides the inner
/// colour) and dashes it with `dashes` intervals of `color` (0: the region without dashes).
void addDashedCentre(DiffusionCurveImage& image, int index, double inset_mm, int dashes,
                     const Color& color, double glyph_size_mm);

}  // namespace vicc_glyphs::design
