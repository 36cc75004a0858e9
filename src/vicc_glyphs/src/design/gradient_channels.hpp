#pragma once
// The gradient glyph's structures (thesis 6.2.5.2, Fig. 6.18A), built from distance
// isolines of a closed contour (pacemod::offsetIsoline):
// - a band along the contour, separated from the rest of the glyph by a new curve at
//   band_mm inside; the band's colour is the glyph's inner colour with its HSV value and
//   saturation scaled (darker and more saturated: more contrast outward, for a growing value;
//   brighter: a shrinking one);
// - a central region, bounded by a new curve at inset_mm inside whose inner side is dashed in
//   a sign colour (PACEMOD colour modification with its inner diffusion barrier).

#include <map>

#include "vicc_glyphs/dci/diffusion_curve.hpp"
#include "vicc_glyphs/pacemod/offset_contour.hpp"

namespace vicc_glyphs::design {

/// Closed curves inset into the closed curves of an image: each curve sampled once, however
/// many insets are taken from it. The curves' geometry must not change meanwhile.
class ContourInsets {
 public:
  explicit ContourInsets(double glyph_size_mm) : glyph_size_mm_(glyph_size_mm) {}
  /// A new closed curve (geometry only) on the isoline `offset_mm` inside curve `index` of
  /// `image`, with that curve's orientation. Throws std::invalid_argument if nothing is left.
  DiffusionCurve inset(const DiffusionCurveImage& image, int index, double offset_mm);

 private:
  double glyph_size_mm_;
  std::map<int, pacemod::Polyline> contours_;
};

/// The side of a closed curve that faces the region it encloses: true = left.
bool enclosedSideIsLeft(const DiffusionCurve& curve);

/// Adds the band curve inside closed curve `index` and recolours the band. Factors of 1 and 1
/// leave the image unchanged. Throws std::invalid_argument if the band leaves no region.
void addContourBand(DiffusionCurveImage& image, int index, ContourInsets& insets, double band_mm,
                    double value_factor, double saturation_factor);

/// Adds the central-region curve inset_mm inside closed curve `index` (both sides the inner
/// colour) and dashes it with `dashes` intervals of `color` (0: the region without dashes).
void addDashedCentre(DiffusionCurveImage& image, int index, ContourInsets& insets, double inset_mm,
                     int dashes, const Color& color, double glyph_size_mm);

}  // namespace vicc_glyphs::design
