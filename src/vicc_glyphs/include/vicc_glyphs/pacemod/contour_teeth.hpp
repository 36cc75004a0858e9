#pragma once
// Sub-pixel teeth of imported icon contours. Icon files carry steps back and forth a fraction
// of a pixel long: MDI's weather-pouring has `...19.5,14 20,13.72V13.73C20.6,13.39...`, a
// segment of 0.01 icon units (0.2 px at 512 px) that leaves the contour at 120 degrees and
// returns. Invisible when rendered, but an offset of the contour turns it into a spike as long
// as the amplitude (its normals point along the contour), and the sharp corners at its ends
// bend the waves beside it. contourCorners already takes joins closer than kOneCornerPx as one
// corner (that turns by all of them, or none); PACEMOD waves the contour with the geometry
// made to match: such a stretch becomes one point.

#include "vicc_glyphs/dci/diffusion_curve.hpp"

namespace vicc_glyphs {
namespace pacemod {

/// `curve` with every tooth removed: a segment shorter than kOneCornerPx (its control polygon)
/// between two sharp joins (each turning by more than kSmoothJoinDegrees), whose neighbours are
/// not that short (a finely flattened arc stays as it is). Its two ends become one point at
/// their middle, a corner that turns by the sum of both joins' turns (none if they cancel); the
/// neighbouring handles move with their ends (their directions stay), and colour and blur
/// positions after it move back by one segment (those on it go to its place). The contour moves
/// by half the tooth's length at most. A curve without teeth is returned as it is; the first
/// and last segment (the seam of a closed curve) are left alone.
DiffusionCurve withoutTeeth(const DiffusionCurve& curve);

}  // namespace pacemod
}  // namespace vicc_glyphs
