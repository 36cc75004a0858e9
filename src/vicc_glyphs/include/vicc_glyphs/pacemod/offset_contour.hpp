#pragma once
// Isolines of the distance to a closed contour (thesis 6.2.3.3, "Shrinking and Inflating of
// Icon Parts" and diffusion barriers): the region the contour encloses, offset by a disc (Clipper's
// round-joined polygon offsetting: every point within the distance of the region, or every point
// of it farther than the distance from its outside), which is exactly the region bounded by the
// isoline; fitted by a closed cubic B-spline (least squares, then Fowler-Bartels pins the closing
// point and equal end tangents), which becomes a Bezier chain.

#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"
#include "vicc_glyphs/pacemod/polyline.hpp"

namespace vicc_glyphs {
namespace pacemod {

/// The isoline at signed distance `offset` (pixels; > 0 outside = inflated, < 0 inside =
/// shrunk) of the region enclosed by the closed `contour` (non-zero winding), as a closed polyline
/// with points at most a quarter pixel apart and the same orientation as `contour`; where the
/// region splits, the largest part; empty when nothing is left or an input is not finite. Its
/// points lie within 0.05 px of the exact isoline, without the loops and hairs that projecting
/// a raster's trace onto it makes at its cusps (withoutSmallLoops, withoutHairs).
Polyline offsetIsoline(const Polyline& contour, double offset);

/// offsetIsoline of the region less every point within `clearance` pixels of the regions of
/// `obstacles` (closed polylines), so that an inflated part stops short of its neighbours;
/// `limited` (if given) says whether that took anything away.
Polyline offsetIsolineAvoiding(const Polyline& contour, double offset,
                               const std::vector<Polyline>& obstacles, double clearance,
                               bool* limited = nullptr);

/// The closed `line` (first == last point) with every loop of at most 1 px along it cut out at
/// its crossing (loops across the closing point are kept).
Polyline withoutSmallLoops(Polyline line);

/// The closed `line` without its hairs: stretches of at most 80 px that run out and back along
/// themselves, their two ends within 0.25 px and enclosing less than 0.25 px times their length
/// (a zero-width crack of a region). The line itself if fewer than 4 points would be left.
Polyline withoutHairs(const Polyline& line);

/// A closed polyline (first == last point) as a closed Bezier chain (3K+1 points) of a
/// least-squares cubic B-spline with knots about `knot_spacing` pixels apart; where the line
/// turns by more than 60 degrees within a pixel (a corner, or a cusp where the offsets of two
/// lobes meet) the chain has a corner through that point, and the pieces between corners are
/// fitted each through its two corners (a smooth fit overshoots a cusp into a loop). Throws
/// std::invalid_argument for fewer than 4 distinct points.
std::vector<Point2> closedBezierFit(const Polyline& line, double knot_spacing = 6.0);

}  // namespace pacemod
}  // namespace vicc_glyphs
