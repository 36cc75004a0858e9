#pragma once
// PACEMOD periodic geometric modification of a whole icon (thesis 6.2.3-6.2.4.1): the entry
// point for designs and the `vicc_glyph modify` command.
//
//   DiffusionCurveImage dci = loadDiffusionCurves("water.svg", 512);
//   WaveSpec spec{Waveform::Sine, /*waves_per_mm=*/0.3, /*amplitude_mm=*/0.5};
//   std::vector<CurveWaveReport> report = applyWaves(dci, selectCurves(dci, {}), spec, 50.0);
//
// Units: the image is `glyph_size_mm` millimetres wide, so one millimetre is
// image.width / glyph_size_mm pixels. Each selected closed curve gets
// round(waves_per_mm * arc length in mm) whole waves (0: left unchanged and reported so);
// open curves are left unchanged and reported as skipped. Colour and blur points keep their
// arc-length positions. Self-intersection prevention: the skeleton half-space test against all
// curves of the unmodified image limits each knot point (thesis 6.2.4.1); as that test only
// looks at the knot points, a polygon check of all resulting curves follows, and the knot points
// within half a period of a remaining crossing get their amplitude halved until no crossing is
// left (an addition to the thesis, needed at sharp concave corners); a crossing that the curve
// between flattened knot points still makes (a neighbouring lobe's flank at a thin spike, a
// swallowtail at a sharp corner) flattens the neighbours too. The report says where.

#include <string>
#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"
#include "vicc_glyphs/pacemod/nearest_curve_point.hpp"
#include "vicc_glyphs/pacemod/polyline.hpp"
#include "vicc_glyphs/pacemod/wave_spec.hpp"

namespace vicc_glyphs {
namespace pacemod {

struct WaveOptions {
  bool prevent_self_intersection = true;
  /// Free space epsilon kept to the skeleton, in mm (0.3 mm = Fig. 6.14's 3 px at 512 px for a
  /// 50 mm glyph).
  double skeleton_offset_mm = 0.3;
  /// Grid pixels per image pixel of the transforms' grid (NearestCurvePoint); its pixel is the
  /// skeleton guard's largest slack.
  double field_grid_scale = 1.0;
  NearestPointMethod nearest_point_method = NearestPointMethod::ExactSegments;
};

/// A knot point whose translation was shortened.
struct PeakReduction {
  double arc_length_mm = 0.0;  ///< along the original contour from its start point
  double allowed_mm = 0.0;     ///< the amplitude applied instead of the requested one
  /// "skeleton": the half-space test of 6.2.4.1; "crossing": the polygon check after it (the
  /// modified contours still crossed near this knot point, so its amplitude was halved, at
  /// most kMaxRepairRounds times, the last time to 0; a crossing that outlives that flattens
  /// the knot points next to the flat stretch, kMaxFlatteningRounds times at most); "corner":
  /// a sine or rectangle knot point on an icon corner, moved into the corner's angle, where the
  /// offset contour of its neighbours meets the bisector (nearer than the amplitude), or a
  /// triangle or sawtooth knot point beside an icon corner whose offset would fall past the
  /// corner's bisector: the half-space test done exactly there (the bisector is the skeleton).
  std::string reason;
};

/// Rounds of the polygon check that follows the skeleton guard.
constexpr int kMaxRepairRounds = 6;
/// Further rounds after those: each sets the knot points next to a crossing whose own window is
/// already flat to 0, so that the flat stretch grows until the crossing is gone.
constexpr int kMaxFlatteningRounds = 8;

struct CurveWaveReport {
  int curve = 0;  ///< index in the image
  double arc_length_mm = 0.0;
  double requested_waves = 0.0;  ///< waves_per_mm * arc length (before rounding)
  int wave_count = 0;            ///< the whole number used (0: not modified)
  int knot_points = 0;           ///< translated knot points (wave peaks and corners)
  double requested_amplitude_mm = 0.0;
  /// Distance of each translated knot point of the modified curve from the original contour
  /// (measured on the result, not the requested value): minimum, mean and maximum.
  double realised_amplitude_min_mm = 0.0;
  double realised_amplitude_mean_mm = 0.0;
  double realised_amplitude_max_mm = 0.0;
  std::vector<PeakReduction> reductions;
  /// Crossings of this curve's polygon with itself or another curve that remain after the
  /// repair rounds (0 in every bench case; reported, never hidden). Crossings that the original
  /// curves have themselves at the same place (contours that touch) are not counted.
  int unresolved_crossings = 0;
  std::string skipped;  ///< non-empty: why the curve was left unchanged
};

/// The skeleton guard's polylines of `curves`: each flattened within 0.005 px, far below the
/// guard's least slack (5 % of a 1 px amplitude), since its nearest points are exact on them.
/// applyWaves passes the contours it waves without their sub-pixel teeth (as their waves are
/// built); the feature-transform bench measures the same polylines.
std::vector<Polyline> skeletonGuardPolylines(const std::vector<DiffusionCurve>& curves);

/// Modifies `image` in place; one report per selected curve, in increasing curve order
/// (duplicate indices are ignored). Throws std::invalid_argument for an invalid spec (message names
/// waves_per_mm / amplitude_mm), glyph_size_mm not finite and > 0, a curve index out of range,
/// or a frequency so high that a quarter period would be shorter than half a pixel.
std::vector<CurveWaveReport> applyWaves(DiffusionCurveImage& image, const std::vector<int>& curves,
                                        const WaveSpec& spec, double glyph_size_mm,
                                        const WaveOptions& options = {});

}  // namespace pacemod
}  // namespace vicc_glyphs
