#pragma once
// The base of the smooth waveforms (sine, rectangle): the least-squares cubic B-spline, on the
// waveform's knots at arc-length positions, of the contour offset by the wave's signed offset
// w(l), parametrised by the original's arc length. Inside an icon corner's angle the offsets of
// the two sides overlap: the offset contour is each side's offset up to the point where it
// reaches the corner's bisector (for a constant w the miter, |w| tan(turn / 2) of arc length
// before the corner; the wave's w changes along the sides). The samples within twice that
// distance (at most half the way to the next corner) take their offset points from the part of
// the side that is left, spread over the whole stretch, so that the fitted curve arrives at the
// meeting point at the corner's arc length without stopping (a spline that had to stand still
// there would loop). Outside the angle the offset contour is a
// circular arc of radius |w| around the corner: the samples within 2 |w| of it take their
// points from the side's offset and half of that arc, so that the curve rounds the corner
// instead of overshooting after a bevel. The normal equations depend
// only on the knots and the sample positions: they are factorised once per contour, so every
// amplitude (each repair round) costs one back substitution.

#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "vicc_glyphs/bspline/arc_length.hpp"
#include "vicc_glyphs/bspline/bspline_curve.hpp"
#include "vicc_glyphs/bspline/fitting.hpp"
#include "vicc_glyphs/pacemod/contour_corners.hpp"
#include "wave_strips.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace detail {

class OffsetFit {
 public:
  /// `knots`: clamped cubic knot vector over [0, L] (L = the table's length); 8 samples per knot
  /// span. `original` and `table` must outlive the fit. Throws std::invalid_argument when the
  /// normal equations are singular.
  OffsetFit(const bspline::BSplineCurve& original, const bspline::ArcLengthTable& table,
            std::vector<double> knots, const std::vector<ContourCorner>& corners, double area);

  using Offset = std::function<double(double arc_length)>;

  /// How the offset contour passes the icon corners, per corner: inside its angle how far along
  /// the side before and the side after it the side's offset reaches the bisector
  /// (meetingDistance; {0, 0} outside the angle), and the point where the offset contour passes
  /// the corner: outside the angle the corner's offset point, inside it the middle of the two
  /// sides' meeting points (each side offset by the offset at its own arc length).
  struct CornerPassage {
    std::vector<std::pair<double, double>> meeting;
    std::vector<Point2> targets;
  };
  /// The meeting distances are the costly part (bisections along the sides): the callers take
  /// them from here once per offset instead of asking meetingDistance again.
  CornerPassage cornerPassage(const Offset& offset) const;

  /// Inside corner c's angle: how far along its side (-1 before, +1 after) the side's offset
  /// reaches the bisector (bisection up to half the way to the next corner; that distance if
  /// it does not).
  double meetingDistance(int c, int side, const Offset& offset) const;

  /// Inside corner c's angle: the stretch along its side (-1 before, +1 after) over which the
  /// samples spread the offset contour left past `meeting` (meetingDistance): kSpreadOver times
  /// it, at most half the way to the next corner.
  double spreadDistance(int c, int side, double meeting) const;

  /// The fit of the contour offset by offset(l) (pixels, positive outward); `passage` from
  /// cornerPassage(offset).
  bspline::BSplineCurve fit(const Offset& offset, const CornerPassage& passage) const;

 private:
  struct Sample {
    double arc_length;
    Point2 point;
    Point2 normal;
    int corner;   ///< nearest icon corner (index) or -1
    int side;     ///< -1 before it, +1 after it, 0 on it
    double room;  ///< how far from the corner its offset contour may take over
  };

  /// Distance from arc length `at` to the next knot after (side +1) or before (-1) it.
  double knotGap(double at, int side) const;

  /// The side's offset point `distance` before (side -1) or after (+1) corner c.
  Point2 sideOffset(int c, int side, double distance, const Offset& offset) const;
  /// The offset contour near corner c at `distance` (< `spread`, the stretch the samples are
  /// spread over) before (side -1) or after (+1) it; `meeting`: meetingDistance inside the
  /// angle.
  Point2 cornerPath(int c, int side, double distance, double spread, double meeting,
                    const Point2& target, const Offset& offset) const;

  std::vector<double> knots_;
  OffsetFrame frame_;
  std::vector<ContourCorner> corners_;
  /// Per corner: half the way to the corner before and to the one after it.
  std::vector<std::pair<double, double>> reach_;
  std::vector<Sample> samples_;
  std::shared_ptr<const bspline::CubicLeastSquares> solver_;
};

}  // namespace detail
}  // namespace pacemod
}  // namespace vicc_glyphs
