#pragma once
// One closed contour with a periodic geometric wave (thesis 6.2.3.3 and 6.2.4.1):
// 1. the contour is re-fitted by least squares onto the layout's knots, now placed at arc-length
//    positions (the spline is re-parametrised by the original's arc length, domain [0, L]);
// 2. the knot points (wave peaks / corners) are translated along the outward normal of a
//    smooth fit with single knots every quarter period (the sine's knots) with alternating signs,
//    each amplitude limited by the skeleton guard if one is given;
// 3. sine: Fowler-Bartels moves the de Boor points so that the curve meets the translated knot
//    points exactly (plus equal first derivatives at the closing point, for a smooth seam);
//    rectangle: the contour is fitted on the knot vector with the corner knots of multiplicity
//    3, its de Boor points moved with their nearest knot point along the normal, then
//    Fowler-Bartels and the flank spans become strips; triangle and sawtooth consist of strips
//    only: every third de Boor point is a corner (Fig. 6.14B) and the two between are fitted to
//    the contour offset linearly from one corner's amplitude to the next. On a straight contour
//    that is the thesis' straight line with the points at a third and two thirds; on a curved
//    contour the strip bends with it, so that the amplitude stays what was asked for.

#include <vector>

#include "vicc_glyphs/bspline/arc_length.hpp"
#include "vicc_glyphs/bspline/bspline_curve.hpp"
#include "vicc_glyphs/pacemod/skeleton_guard.hpp"
#include "vicc_glyphs/pacemod/wave_layout.hpp"

namespace vicc_glyphs {
namespace pacemod {

struct ContourWave {
  bspline::BSplineCurve curve;  ///< modified contour over [0, L] (L = original arc length)
  WaveLayout layout;
  std::vector<Point2> knot_points;   ///< per layout peak: the original contour point k
  std::vector<Point2> directions;    ///< per layout peak: unit translation direction (sign * n)
  std::vector<GuardResult> guarded;  ///< per layout peak: the amplitude actually applied
  std::vector<bool> capped;          ///< per layout peak: limited by `caps` (crossing repair)
  /// per layout peak: the translation length; the amplitude, or with stretch_at_corners next to a
  /// sharp convex corner of the contour longer, so that the translated knot point still ends
  /// `amplitude` away from the contour (the distance the amplitude is measured by).
  std::vector<double> translations;
};

/// What a contour's wave is built on and that does not depend on the amplitudes: the layout,
/// the smooth fit whose normals translate the knot points, and for the rectangle the fit on its
/// knot vector with triple corners. Built once per contour, reused by every repair round.
struct ContourFrame {
  WaveLayout layout;
  bspline::BSplineCurve frame_fit;  ///< single knots every quarter period (+ the icon's corners)
  double area = 0.0;                ///< signed area of frame_fit (orientation of the normals)
  bspline::BSplineCurve rectangle_fit;  ///< Rectangle only: the fit on the rectangle's knots
};

/// Throws std::invalid_argument for an open curve or wave_count < 1.
ContourFrame contourFrame(const bspline::BSplineCurve& original,
                          const bspline::ArcLengthTable& table, Waveform waveform, int wave_count);

/// The wave on a frame built from the same `original` and `table` by contourFrame.
ContourWave modifyContour(const ContourFrame& frame, const bspline::BSplineCurve& original,
                          const bspline::ArcLengthTable& table, double amplitude,
                          const SkeletonGuard* guard, const std::vector<double>& caps = {},
                          bool stretch_at_corners = false);

/// `original` must be closed (first == last point) and have a tangent everywhere; `table` its
/// arc-length table; amplitude in image pixels (>= 0); `guard` may be null (no prevention);
/// `caps`: empty, or per layout peak an upper bound on its amplitude (pixels);
/// `stretch_at_corners`: lengthen translations next to sharp convex corners (see translations).
/// Throws std::invalid_argument for an open curve or wave_count < 1.
ContourWave modifyContour(const bspline::BSplineCurve& original,
                          const bspline::ArcLengthTable& table, Waveform waveform, int wave_count,
                          double amplitude, const SkeletonGuard* guard,
                          const std::vector<double>& caps = {}, bool stretch_at_corners = false);

/// Least-squares fit (normal equations, sparse Cholesky) of `original` onto `knots` (a clamped
/// cubic knot vector over [0, L]) with the spline parameter equal to the original's arc length: 8
/// samples per knot span.
bspline::BSplineCurve fitOnArcLength(const bspline::BSplineCurve& original,
                                     const bspline::ArcLengthTable& table,
                                     const std::vector<double>& knots);

/// Index of the de Boor point the curve passes through at a knot of multiplicity >= degree
/// (or a domain end) of a clamped cubic; throws std::invalid_argument elsewhere.
int cornerControlIndex(const bspline::BSplineCurve& curve, double knot);

}  // namespace pacemod
}  // namespace vicc_glyphs
