#pragma once
// Strokes as filled areas: every subpath is flattened and offset by half the stroke width in
// its user space with Clipper's polygon offsetting (joins: miter with the miter limit, round,
// bevel; caps: butt, round, square; optional dashes), then mapped to pixels, so non-uniform
// transforms stretch the stroke as SVG does.

#include <vector>

#include "clipper_geometry.hpp"
#include "svg_transform.hpp"

namespace vicc_glyphs {
namespace io_detail {

enum class LineCap { kButt, kRound, kSquare };
enum class LineJoin { kMiter, kRound, kBevel };

struct StrokeGeometry {
  double width = 1.0;
  LineCap cap = LineCap::kButt;
  LineJoin join = LineJoin::kMiter;
  double miter_limit = 4.0;
  std::vector<double> dashes;  ///< user units, even count (SVG repeats odd lists); empty: solid
  double dash_offset = 0.0;
};

/// The area the stroke of `subpaths` (user coordinates) covers, in the frame's pixel integers.
/// `tolerance` is the flattening tolerance in pixels. Throws std::invalid_argument when the
/// geometry is out of Clipper's range.
Paths strokeArea(const std::vector<Subpath>& subpaths, const Affine2& user_to_pixels,
                 const StrokeGeometry& stroke, const IntegerFrame& frame, double tolerance,
                 VertexBudget& budget);

/// Splits a polyline into its dashes (open polylines), starting `offset` into the pattern.
std::vector<std::vector<Point2>> dashPolyline(const std::vector<Point2>& polyline,
                                              const std::vector<double>& dashes, double offset);

}  // namespace io_detail
}  // namespace vicc_glyphs
