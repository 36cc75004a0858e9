#pragma once
// The conventions of Orzan's XML format in one place, shared by reader and writer
// (verified against published samples and independent readers, see the package docs):
// - <control_point x= y=> stores image row in x and image column in y, so file x = our y;
// - colours are B, G, R in 0..255;
// - colour and blur points sit at globalID = 10 * s along a curve of K segments (0..10K);
// - swapping x and y mirrors the plane, so the file's left side is our right side;
// - a side without colour constraints (a diffusion barrier) is marked boundary="Neumann" on its
//   colour set, as in the SceneXML variant of the format.

namespace vicc_glyphs {
namespace io_detail {

constexpr double kGlobalIdPerSegment = 10.0;
constexpr double kColorScale = 255.0;
constexpr const char* kBarrierBoundary = "Neumann";

}  // namespace io_detail
}  // namespace vicc_glyphs
