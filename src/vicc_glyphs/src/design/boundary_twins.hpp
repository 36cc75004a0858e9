#pragma once
// The SVG import gives every colour region its own boundary curves, so where a region lies in a
// hole of another (the brain inside the head) the boundary exists twice: as the hole of the
// outer region and as the inner region's outline, reversed, with the side colours swapped. An
// encoding naming one of the two would leave the other's colour and geometry behind (a brain
// half in its category colour, half in the icon's pink). The copy adds no constraint to the
// diffusion, so the design code drops it before the encodings act.

#include "vicc_glyphs/dci/diffusion_curve.hpp"

namespace vicc_glyphs::design {

/// Removes each curve that runs along another closed curve in the opposite direction with the
/// same single colour on the swapped sides (and the same blur) and has the region it encloses
/// on its right (a hole); the outline with its region on the left stays. Curves whose colours
/// change along them are kept. Returns the number of curves removed.
int removeBoundaryTwins(DiffusionCurveImage& image);

}  // namespace vicc_glyphs::design
