#pragma once
// One closed contour with a periodic geometric wave (thesis 6.2.3.3 and 6.2.4.1). The wave is an
// offset of the contour by a signed amount that alternates between +-amplitude at the layout's
// knot points:
// 1. the knots are placed at arc-length positions (the spline is re-parametrised by the
//    original's arc length, domain [0, L]); the icon's own corners stay corners (triple knots
//    at their arc lengths);
// 2. the knot points (wave peaks / corners) are translated along the contour's outward normal
//    with alternating signs, each amplitude limited by the skeleton guard if one is given. A
//    knot point on an icon corner, or so near one that inside the corner's angle its offset
//    would fall past the bisector (contour_corners.hpp), moves onto the corner and along its
//    bisector, to the corner's offset point; where its neighbours leave no room to move, a
//    strip knot point (triangle, sawtooth) still goes to that offset point (the miter), at its
//    own arc length, instead of to its own offset point, which lies nearer the corner's other
//    side than the amplitude (while the amplitude it keeps after the guard and the caps does);
// 3. sine and rectangle: the contour offset by the wave's profile between the knot points (the
//    sine's half cosines, the rectangle's plateaus and linear flanks) is fitted by least squares
//    on the knots (offset_fit.hpp; the rectangle's corners with multiplicity 3), then
//    Fowler-Bartels moves the de Boor points so that the curve meets the translated knot points
//    and the icon's corners their offset points exactly (equal first derivatives at a smooth
//    closing point), and the rectangle's flank spans become strips;
//    triangle and sawtooth consist of strips only: every third de Boor point is a corner (Fig.
//    6.14B), the two between follow the contour offset linearly from one corner's amplitude to
//    the next (wave_strips.hpp), and an icon corner inside a strip splits it at its offset point;
//    a long strip on a bend that one cubic cannot follow within 0.05 px is split at its middle
//    (further C0 knots: degrees of freedom where the contour needs them);
// 4. between consecutive knot points translated by exactly 0 the curve is the original's
//    pieces (original_splice.hpp).

#include <memory>
#include <vector>

#include "vicc_glyphs/bspline/arc_length.hpp"
#include "vicc_glyphs/bspline/bspline_curve.hpp"
#include "vicc_glyphs/pacemod/contour_corners.hpp"
#include "vicc_glyphs/pacemod/skeleton_guard.hpp"
#include "vicc_glyphs/pacemod/wave_layout.hpp"

namespace vicc_glyphs {
namespace pacemod {

struct ContourWave {
  bspline::BSplineCurve curve;  ///< modified contour over [0, L] (L = original arc length)
  WaveLayout layout;
  /// Per layout peak: the spline parameter (= arc length) where the curve meets the translated
  /// knot point: the peak's own, or that of the icon corner it moved onto.
  std::vector<double> parameters;
  /// Per layout peak: the icon corner (index in ContourFrame::corners) whose offset point it
  /// goes to, or -1.
  std::vector<int> on_corner;
  std::vector<Point2> knot_points;   ///< per layout peak: the contour point k it moves from
  std::vector<Point2> directions;    ///< per layout peak: unit translation direction (sign * n)
  std::vector<GuardResult> guarded;  ///< per layout peak: the amplitude actually applied
  std::vector<bool> capped;          ///< per layout peak: limited by `caps` (crossing repair)
  /// Per layout peak: limited at an icon corner. Sine, rectangle: inside the corner's angle
  /// the knot point gets the distance where the sides' offset contour meets the bisector.
  /// Triangle, sawtooth: a knot point beside the corner whose offset would fall past the
  /// bisector gets the offset that reaches it, less the guard's epsilon.
  std::vector<bool> cornered;
  /// Per layout peak: its offset falls past the bisector of an icon corner (inside the angle)
  /// and the offset fit decides the curve there (sine, rectangle; no constraint of its own).
  std::vector<bool> swallowed;
  /// Per layout peak: the translation length. The amplitude (the distance from the contour),
  /// except along a corner's bisector inside its angle: there the miter, amplitude / cos(turn/2).
  std::vector<double> translations;
};

namespace detail {
class OffsetFit;
struct FrameSamples;
}  // namespace detail

/// What a contour's wave is built on and that does not depend on the amplitudes: the layout,
/// the contour's corners, the original's points and normals where every wave takes them and,
/// for the sine and the rectangle, the factorised least-squares fit onto their knots. Built
/// once per contour, reused by every repair round.
struct ContourFrame {
  WaveLayout layout;
  double area = 0.0;                   ///< signed area of the original (orientation)
  std::vector<ContourCorner> corners;  ///< of the original contour
  std::shared_ptr<const detail::OffsetFit> offset_fit;  ///< sine and rectangle
  std::shared_ptr<const detail::FrameSamples> samples;
};

/// Throws std::invalid_argument for an open curve or wave_count < 1.
ContourFrame contourFrame(const bspline::BSplineCurve& original,
                          const bspline::ArcLengthTable& table, Waveform waveform, int wave_count);

/// Where a contour's knot points go and how far the skeleton guard lets each (its nearest-point
/// searches), kept from one modifyContour call to the next: the repair rounds rebuild a contour
/// on the same frame with the same amplitude and guard, with new caps on a few knot points, and
/// a knot point's verdict depends on its own cap only. Starts afresh when the frame, the
/// amplitude or the guard change (frame and guard compared by address: they must stay alive,
/// unchanged, while their verdicts are kept). One per contour; not for concurrent calls.
class GuardVerdicts {
 public:
  GuardVerdicts();
  ~GuardVerdicts();
  GuardVerdicts(GuardVerdicts&&) noexcept;
  GuardVerdicts& operator=(GuardVerdicts&&) noexcept;

  struct Store;  ///< defined with modifyContour
  Store& store() { return *store_; }

 private:
  std::unique_ptr<Store> store_;
};

/// The wave on a frame built from the same `original` and `table` by contourFrame; the same
/// wave with or without `verdicts` (which only saves the guard's work in later calls).
ContourWave modifyContour(const ContourFrame& frame, const bspline::BSplineCurve& original,
                          const bspline::ArcLengthTable& table, double amplitude,
                          const SkeletonGuard* guard, const std::vector<double>& caps = {},
                          GuardVerdicts* verdicts = nullptr);

/// `original` must be closed (first == last point) and have a tangent everywhere; `table` its
/// arc-length table; amplitude in image pixels (>= 0); `guard` may be null (no prevention);
/// `caps`: empty, or per layout peak an upper bound on its amplitude (pixels).
/// Throws std::invalid_argument for an open curve or wave_count < 1.
ContourWave modifyContour(const bspline::BSplineCurve& original,
                          const bspline::ArcLengthTable& table, Waveform waveform, int wave_count,
                          double amplitude, const SkeletonGuard* guard,
                          const std::vector<double>& caps = {});

/// Index of the de Boor point the curve passes through at a knot of multiplicity >= degree
/// (or a domain end) of a clamped cubic; throws std::invalid_argument elsewhere.
int cornerControlIndex(const bspline::BSplineCurve& curve, double knot);

}  // namespace pacemod
}  // namespace vicc_glyphs
