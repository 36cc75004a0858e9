#pragma once
// PACEMOD periodic colour modification (thesis 6.2.4.2, Fig. 6.15): the inner side of a closed
// contour is split into 2N equidistant arc-length intervals that alternate between the original
// colour and a dash colour, with hard transitions (a pair of colour points a small arc length
// before and after every interval boundary); a diffusion barrier, the distance-field isoline a
// small offset inside, keeps the dashes to a band along the contour: it emits nothing towards
// the contour and the original inner colour towards the inside.
// The geometry of the dashed curve is not touched (colour positions are placed on its Bezier
// chain directly). The barrier follows the contour's own region only (holes inside it are not
// taken into account).

#include <string>
#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"

namespace vicc_glyphs {
namespace pacemod {

struct DashSpec {
  int count = 6;                   ///< dashes along each contour, >= 1
  Color color{0.5, 0.5, 0.5};      ///< dash colour, linear RGB in [0, 1]
  double transition_mm = 0.05;     ///< each colour point of a pair sits this far from the boundary
  double barrier_offset_mm = 0.6;  ///< the barrier's distance inside the contour; 0: no barrier
};

struct CurveDashReport {
  int curve = 0;
  int dashes = 0;  ///< 0: not dashed (see skipped)
  double dash_length_mm = 0.0;
  int barrier_curve = -1;  ///< index of the added barrier curve, -1 if none
  std::string skipped;
};

/// Empty when valid, else a message naming the field (count, color, transition_mm,
/// barrier_offset_mm).
std::string validate(const DashSpec& spec);

/// Dashes the selected closed curves; barriers are appended to image.curves. Throws
/// std::invalid_argument for an invalid spec, glyph size or curve index.
std::vector<CurveDashReport> applyDashes(DiffusionCurveImage& image, const std::vector<int>& curves,
                                         const DashSpec& spec, double glyph_size_mm);

/// Arc length along a Bezier chain: s <-> l by a dense chord-length table.
class ChainArcLength {
 public:
  explicit ChainArcLength(const DiffusionCurve& curve, int samples_per_segment = 64);
  double totalLength() const { return lengths_.back(); }
  double parameterAt(double length) const;  ///< s in [0, K] for l (clamped)

 private:
  std::vector<double> parameters_;
  std::vector<double> lengths_;
};

}  // namespace pacemod
}  // namespace vicc_glyphs
