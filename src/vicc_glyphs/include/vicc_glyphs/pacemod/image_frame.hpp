#pragma once
// Whether a modification carried curves out of the image frame: the renderer clips them, and
// part of the encoding (waves, an inflated region) would be cut off without a word.

#include <optional>
#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"

namespace vicc_glyphs {
namespace pacemod {

/// How far the sampled curve reaches beyond the width x height frame, in pixels (<= 0 inside).
double reachBeyondFrame(const DiffusionCurve& curve, int width, int height);

/// The first of `curves` (indices into both images) that lay inside the frame of `before`
/// (within half a pixel) and reaches more than half a pixel beyond the frame of `after`.
/// Curves that already reached beyond the frame before are not counted.
std::optional<int> curveCarriedOutOfFrame(const DiffusionCurveImage& before,
                                          const DiffusionCurveImage& after,
                                          const std::vector<int>& curves);

}  // namespace pacemod
}  // namespace vicc_glyphs
