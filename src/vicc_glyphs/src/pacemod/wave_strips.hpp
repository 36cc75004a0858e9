#pragma once
// The straight strips of the sharp waveforms (thesis 6.2.4.1, Fig. 6.14B): cubic pieces between
// two C0 corners whose inner de Boor points follow the contour offset linearly from one end's
// offset to the other's. On a straight contour that is the line with its points at a third and
// two thirds; on a curved one the strip bends with the contour, so that the wave keeps its
// amplitude (a chord would lose the sagitta). Next to an icon corner the offset points past the
// corner's bisector are left out (inside the angle the offset contour ends at the miter).

#include <limits>
#include <vector>

#include "vicc_glyphs/bspline/arc_length.hpp"
#include "vicc_glyphs/bspline/bspline_curve.hpp"
#include "vicc_glyphs/pacemod/contour_corners.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace detail {

/// The original's point and outward normal at one arc length: the offset point by w is
/// point + w * normal.
struct ContourSample {
  Point2 point = Point2::Zero();
  Point2 normal = Point2::Zero();
};

/// The original contour (parametrised by its arc length through `table`) and its orientation.
struct OffsetFrame {
  const bspline::BSplineCurve& original;
  const bspline::ArcLengthTable& table;
  double area;  ///< signed area of the contour (orientation of the normals)

  /// Outward unit normal of the original at arc length l (at a corner: the side after it).
  Point2 normal(double l) const;
  /// The original's point at arc length l moved by w along normal(l).
  Point2 offsetPoint(double l, double w) const;
  /// The original's point and normal(l) at arc length l.
  ContourSample sample(double l) const;
  /// sample(l) for each of `lengths`, which must not decrease: the arc-length table and the
  /// knot spans are walked in order instead of searched three times per sample.
  std::vector<ContourSample> samples(const std::vector<double>& lengths) const;

 private:
  /// The outward normal of the chord from the original's point `before` to `after` around arc
  /// length l (the tangent at l where the chord has no length).
  Point2 normalOfChord(const Point2& before, const Point2& after, double l) const;
};

/// A strip piece: arc lengths and offsets at its ends, and the icon corner at either end (null
/// for a wave corner or a smooth place).
struct StripPiece {
  double l0 = 0.0, l1 = 0.0, w0 = 0.0, w1 = 0.0;
  const ContourCorner* corner_at_begin = nullptr;
  const ContourCorner* corner_at_end = nullptr;
  /// Where each end's icon corner lies, as an arc length in the frame of l0 and l1 (the
  /// closing corner at 0 or L, whichever is nearer; NaN: at the end's own arc length). A knot
  /// point sent to a corner's miter keeps its own arc length on the side.
  double corner_arc_at_begin = std::numeric_limits<double>::quiet_NaN();
  double corner_arc_at_end = std::numeric_limits<double>::quiet_NaN();

  /// The side (-1 before it, +1 after it) of the icon corner at the piece's begin
  /// (`at_begin`) or end whose offset points the samples are tested against (the bisector
  /// test): the side after a corner at the begin, before one at the end, unless the corner
  /// lies beyond the piece's other end (a knot point at the miter of a corner further along:
  /// the leaf's tip, 5 px on). Where the corner lies inside the piece the samples before it
  /// stay on the side after it: those are the swallowtail of the side the knot point came
  /// from, the way from the miter back to the other side (left out, the path jumps from the
  /// miter to the other side's offset and the strip turns sharply there).
  int cornerSide(bool at_begin) const;
};

/// How far a fitted strip leaves the offset path it follows (at the path's points).
struct StripDeviation {
  double largest = 0.0;
  /// The largest over the half of the piece away from the icon corner at one of its ends (0
  /// when it has an icon corner at both ends or none): there the path is the plain offset of
  /// the contour, whatever the corner does to the other half.
  double away_from_corner = 0.0;
};

/// Sets points[first + 1] and points[first + 2], the inner de Boor points of the cubic piece
/// points[first .. first + 3] (its ends stay), by least squares with chord-length parameters.
StripDeviation fitStrip(std::vector<Point2>& points, int first, const StripPiece& piece,
                        const OffsetFrame& frame);
/// The places inside a piece from arc length l0 to l1 that its strip follows. They do not
/// depend on the offsets: a piece fitted for several amplitudes needs them once.
std::vector<ContourSample> stripSamples(const OffsetFrame& frame, double l0, double l1);
/// fitStrip on `samples` = stripSamples(frame, piece.l0, piece.l1).
StripDeviation fitStrip(std::vector<Point2>& points, int first, const StripPiece& piece,
                        const std::vector<ContourSample>& samples);

}  // namespace detail
}  // namespace pacemod
}  // namespace vicc_glyphs
