#pragma once
// Strokes as filled areas from offset curves of the Beziers themselves: the alternative to
// svg_stroke.cpp's Clipper offsetting of the flattened path (SvgImportOptions::stroke_outliner).
//
// Every cubic is split at cusps (where it becomes its own join), inflections and where its
// radius of curvature equals half the stroke width; each piece's offset at +-width/2 is
// approximated by cubics (true end points and tangents, inner control lengths by least squares,
// halved until within the tolerance). The stroke is then the nonzero union of pieces that each
// cover their part of the stroke once (side of a piece between centreline and offset; where
// the offset folds back, the parts before and beyond the evolute separately), join wedges and
// caps. A single self-overlapping outline would instead cancel (winding +1 - 1 = 0) where a
// folded offset overlaps the stroke, leaving holes at tight turns.

#include <vector>

#include "svg_stroke.hpp"

namespace vicc_glyphs {
namespace io_detail {

/// Same contract as strokeArea (pixel integers of the frame, `tolerance` in pixels, budget and
/// range checks). Dashed strokes fall back to strokeArea (Clipper), see docs/import.md.
Paths curveStrokeArea(const std::vector<Subpath>& subpaths, const Affine2& user_to_pixels,
                      const StrokeGeometry& stroke, const IntegerFrame& frame, double tolerance,
                      VertexBudget& budget);

}  // namespace io_detail
}  // namespace vicc_glyphs
