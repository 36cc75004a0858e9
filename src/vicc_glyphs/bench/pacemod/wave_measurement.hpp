#pragma once
// Independent measurements of a PACEMOD wave on the finished glyph (used by the bench and the
// fast GoogleTest subset): the signed distance of the modified contour to the original one
// (exact point-to-polyline distances: the distance field of the original evaluated along the
// modified curve; positive outside the original region), split into lobes of one sign.

#include <functional>
#include <vector>

#include "vicc_glyphs/pacemod/polyline.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace measure {

struct Lobe {
  int sign = 0;             ///< +1 outside the original region, -1 inside
  double extreme_px = 0.0;  ///< largest |distance| in the lobe
  /// Where the lobe lies along the original: the position (a fraction of the original's length,
  /// in [0, 1)) of the nearest original point of its first and its last sample; begin > end
  /// when the lobe runs over the original's start.
  double arc_begin = 0.0;
  double arc_end = 0.0;
  Point2 extreme_point = Point2::Zero();  ///< the modified contour's sample farthest out
};

struct ContourMeasure {
  std::vector<Lobe> lobes;  ///< cyclic runs of samples beyond the threshold, one sign each
  int outward = 0;          ///< lobes with sign +1
  int inward = 0;
};

/// `original`, `modified`: closed polylines (first == last). A sample belongs to no lobe when
/// |d| <= threshold(position of its nearest original point, as a fraction of the length); a lobe
/// ends where the sign flips (samples below the threshold between two of one sign do not split
/// it).
ContourMeasure measureContour(const Polyline& original, const Polyline& modified,
                              const std::function<double(double arc_fraction)>& threshold);

}  // namespace measure
}  // namespace pacemod
}  // namespace vicc_glyphs
