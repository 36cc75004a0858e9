#pragma once
// The conventions of Orzan's XML format in one place, shared by reader and writer.
// - <control_point x= y=> stores image row in x and image column in y, so file x = our y;
// - colours are B, G, R in 0..255 (the attribute named B holds red, R holds blue);
// - colour and blur points sit at globalID = 10 * s along a curve of K segments (0..10K);
// - the file's left side is our left side, i.e. after the x/y swap the left colours lie on
//   the (dy, -dx) side of the tangent (dx, dy) in image coordinates;
// - a side without colour constraints (a diffusion barrier) is marked boundary="Neumann" on its
//   colour set, as in the SceneXML variant of the format.
// Verified against the published "lady_bug" sample of Orzan et al. (its closed spot curves,
// e.g. the 4th curve, must come out dark inside and red outside, which holds only with
// left = left) and against the Orzan reader of small-usvg (Tian and Guenther, MIT), which swaps
// x/y, R/B and the sides but uses the opposite normal (-dy, dx) for "left"; the two swaps cancel.
// Details in docs/rendering.md ("Orzan XML conventions").

namespace vicc_glyphs {
namespace io_detail {

constexpr double kGlobalIdPerSegment = 10.0;
constexpr double kColorScale = 255.0;
constexpr const char* kBarrierBoundary = "Neumann";

}  // namespace io_detail
}  // namespace vicc_glyphs
