#pragma once
// Independent measurements of a PACEMOD wave on the finished glyph (used by the bench and the
// fast GoogleTest subset): the signed distance of the modified contour to the original one
// (exact point-to-polyline distances: the distance field evaluated along the modified curve;
// positive outside the original region), split into lobes of one sign.

#include <vector>

#include "vicc_glyphs/pacemod/polyline.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace measure {

struct Lobe {
  int sign = 0;             ///< +1 outside the original region, -1 inside
  double extreme_px = 0.0;  ///< largest |distance| in the lobe
  double arc_begin =
      0.0;  ///< arc length along the original of the lobe's first sample's nearest point
  double arc_end = 0.0;
};

struct ContourMeasure {
  std::vector<Lobe> lobes;  ///< cyclic runs of samples with |d| > threshold of one sign
  int outward = 0;          ///< lobes with sign +1: the counted waves
  int inward = 0;
};

/// `original`, `modified`: closed polylines (first == last). Samples with |d| <= threshold
/// belong to no lobe; a lobe ends where the sign flips.
ContourMeasure measureContour(const Polyline& original, const Polyline& modified,
                              double threshold_px);

}  // namespace measure
}  // namespace pacemod
}  // namespace vicc_glyphs
