#pragma once
// Bends of the rectangle wave's offset profile at simple knots. The profile is linear between
// knot points: flat on a plateau, a ramp where the skeleton guard or a repair cap reduced a knot
// point. Next to such a ramp the profile bends at a knot point whose knot is simple, and a C2
// cubic on those knots cannot follow the bend: the least-squares fit rings beside it and the
// Fowler-Bartels step that pins the knot points lifts the plateau's span next to it by up to a
// tenth of the step (the leaf's slit by its stem at 0.1 mm: 1.13 px for 1.02). There a knot is
// inserted in the middle of each knot point span of the bend's window (Boehm: the curve is
// unchanged), and the de Boor points whose support meets the window are fitted again to the
// offset path by least squares, with the curve held at the knot points it met before.

#include <functional>
#include <vector>

#include "vicc_glyphs/bspline/bspline_curve.hpp"
#include "vicc_glyphs/bspline/fowler_bartels.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace detail {

/// The stretch of arc length from the knot point before a bend to the one after it, and the
/// knot point parameters inside it (bends and neighbours, increasing, both ends included).
struct BendWindow {
  std::vector<double> knot_points;
};

/// The offset path the curve should follow at arc length l.
using OffsetPath = std::function<Point2(double l)>;

/// `curve` with each window whose curve leaves `path` by more than `tolerance` (px) refitted,
/// where that brings it nearer to the path (the largest distance at 4 samples per span over the
/// de Boor points' support). `pinned`: the positions the curve
/// must keep (the knot points and icon corners Fowler-Bartels met). `keep_out`: arc lengths (icon
/// corners) near which `path` is not the offset contour: a window whose support reaches one is
/// left as it is, as is one that reaches the curve's ends (the seam).
bspline::BSplineCurve refitBends(const bspline::BSplineCurve& curve,
                                 const std::vector<BendWindow>& windows,
                                 const std::vector<bspline::CurveConstraint>& pinned,
                                 const std::vector<double>& keep_out, const OffsetPath& path,
                                 double tolerance);

}  // namespace detail
}  // namespace pacemod
}  // namespace vicc_glyphs
