#pragma once
// Local curve properties (thesis 2.5.4) in the plane, in the y-down image frame of
// diffusion_curve.hpp. For a tangent (dx, dy) the left normal is (dy, -dx): the side on the
// left when walking along the curve as seen on screen.

#include "vicc_glyphs/bspline/bspline_curve.hpp"

namespace vicc_glyphs {
namespace bspline {

/// Frenet frame at a curve point. In 2D the binormal of Eq. 2.49 is +-z, so the frame reduces
/// to the unit tangent and the unit normal that points towards the centre of curvature.
struct FrenetFrame {
  Point2 position = Point2::Zero();
  Point2 tangent = Point2::UnitX();
  /// Towards the centre of curvature; equals the left normal where the curve is straight.
  Point2 normal = Point2::UnitY();
  /// Signed curvature: positive when the curve bends towards its left normal (on screen).
  double curvature = 0.0;
};

/// Throws std::invalid_argument where the first derivative vanishes (no tangent exists).
FrenetFrame frenetFrameAt(const BSplineCurve& curve, double u);

/// Signed curvature (x'y'' - y'x'') / |s'|^3 with the sign convention of FrenetFrame: positive
/// when bending to the left on screen. Throws where s' vanishes.
double signedCurvatureAt(const BSplineCurve& curve, double u);

/// Unit left normal (dy, -dx) / |(dx, dy)|; throws where s' vanishes.
Point2 leftNormalAt(const BSplineCurve& curve, double u);

/// Shoelace area of the polygon through `samples_per_span` points per knot span, closed by the
/// chord from the end back to the start. In the y-down frame it is positive when the curve runs
/// clockwise on screen (then the enclosed region lies on the right).
double signedArea(const BSplineCurve& curve, int samples_per_span = 32);

/// Unit normal pointing into the region enclosed by a closed curve: the right normal for a
/// positive signedArea (clockwise on screen), the left normal otherwise. For an open curve the
/// region is the one closed by the chord between its ends. Throws where s' vanishes or when the
/// enclosed area is zero.
/// Samples the curve for signedArea on every call; use the overload below in loops.
Point2 inwardNormalAt(const BSplineCurve& curve, double u);
/// Same with the orientation given by a precomputed signedArea(curve).
Point2 inwardNormalAt(const BSplineCurve& curve, double u, double signed_area);

}  // namespace bspline
}  // namespace vicc_glyphs
