#pragma once
// The straight strips of the sharp waveforms (thesis 6.2.4.1, Fig. 6.14B): cubic pieces between
// two C0 corners whose inner de Boor points follow the contour offset linearly from one end's
// offset to the other's. On a straight contour that is the line with its points at a third and
// two thirds; on a curved one the strip bends with the contour, so that the wave keeps its
// amplitude (a chord would lose the sagitta). Next to an icon corner the offset points past the
// corner's bisector are left out (inside the angle the offset contour ends at the miter).

#include <vector>

#include "vicc_glyphs/bspline/arc_length.hpp"
#include "vicc_glyphs/bspline/bspline_curve.hpp"
#include "vicc_glyphs/pacemod/contour_corners.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace detail {

/// The original contour (parametrised by its arc length through `table`) and its orientation.
struct OffsetFrame {
  const bspline::BSplineCurve& original;
  const bspline::ArcLengthTable& table;
  double area;  ///< signed area of the contour (orientation of the normals)

  /// Outward unit normal of the original at arc length l (at a corner: the side after it).
  Point2 normal(double l) const;
  /// The original's point at arc length l moved by w along normal(l).
  Point2 offsetPoint(double l, double w) const;
};

/// A strip piece: arc lengths and offsets at its ends, and the icon corner at either end (null
/// for a wave corner or a smooth place).
struct StripPiece {
  double l0 = 0.0, l1 = 0.0, w0 = 0.0, w1 = 0.0;
  const ContourCorner* corner_at_begin = nullptr;
  const ContourCorner* corner_at_end = nullptr;
};

/// Sets points[first + 1] and points[first + 2], the inner de Boor points of the cubic piece
/// points[first .. first + 3] (its ends stay), by least squares with chord-length parameters.
void fitStrip(std::vector<Point2>& points, int first, const StripPiece& piece,
              const OffsetFrame& frame);

}  // namespace detail
}  // namespace pacemod
}  // namespace vicc_glyphs
