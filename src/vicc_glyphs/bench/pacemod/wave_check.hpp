#pragma once
// The per-glyph checks of the PACEMOD bench and its GoogleTest subset: wave counts, lobe
// amplitudes against the applied amplitudes, new polygon crossings and new sharp turns.
//
// A contour whose knot points all kept the requested amplitude must show exactly its whole
// wave count of outward and of inward lobes, each within 10 % of the amplitude. Where
// self-intersection prevention reduced knot points (the report lists them), the expected lobes
// follow from the amplitudes applied: runs of knot points of one sign form a lobe, a run cut to
// nearly nothing leaves none (its neighbours merge); such lobes are rated against the largest
// amplitude applied in them ("reduced lobes"), not against the request.

#include <string>
#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"
#include "vicc_glyphs/pacemod/periodic_waves.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace measure {

constexpr double kAmplitudeTolerance = 0.10;
/// Lobes whose expected amplitude is below this many pixels are not rated relatively.
constexpr double kMinCheckedAmplitudePx = 0.5;
/// A sample belongs to a lobe when its distance exceeds this fraction of the amplitude applied
/// around it (interpolated between the knot points) ...
constexpr double kLobeThreshold = 0.25;
/// ... and at least this many pixels (the accuracy of the re-fit and of the polylines).
constexpr double kMinLobeThresholdPx = 0.2;
/// A run of knot points cut below this (px) leaves no lobe; one at or above kVisiblePx leaves
/// one; in between the count is not decidable.
constexpr double kInvisiblePx = 0.5 * kMinLobeThresholdPx;
constexpr double kVisiblePx = 2.0 * kMinLobeThresholdPx;
/// A sample step of the polylines (16 per Bezier segment) that turns by more than this against
/// the one before is a sharp turn: a fold, a spike or a hook, which neither the lobes nor the
/// crossings show (a curve that doubles back on itself need not cross itself).
constexpr double kSharpTurnDegrees = 170.0;
/// A sharp turn of the result within this distance of one of the original is not new (px).
constexpr double kSameTurnPx = 1.0;
/// The crossings are those of the polylines the renderer draws (dci/flattening.hpp, which the
/// polygon repair searches) and those of 16 points per Bezier segment, which are finer on
/// short, nearly straight segments; of the latter a loop shorter than this along the curve
/// (px), far below what the renderer's pieces (0.02 px from the curve) can show, is counted
/// apart as a sub-pixel loop.
constexpr double kSubpixelLoopPx = 0.05;

struct GlyphCheck {
  int contours = 0;             ///< modified contours (wave count >= 1)
  int unreduced_contours = 0;   ///< every knot point at the requested amplitude
  int unreduced_count_ok = 0;   ///< of those: wave count outward and inward lobes
  int reduced_decidable = 0;    ///< reduced contours whose lobe count is decidable
  int reduced_count_ok = 0;     ///< of those: the lobes expected from the applied amplitudes
  int reduced_undecidable = 0;  ///< a run of knot points cut to kInvisiblePx..kVisiblePx
  int full_lobes = 0;           ///< lobes whose knot points all kept the requested amplitude
  int full_lobes_ok = 0;        ///< |extreme - expected| <= 10 % of expected
  int reduced_lobes = 0;        ///< lobes around reduced knot points (rated against those)
  int reduced_lobes_ok = 0;
  int reduced_peaks = 0;       ///< knot points self-intersection prevention shortened
  int crossing_peaks = 0;      ///< of those: by the polygon check (reason "crossing")
  int new_crossings = 0;       ///< polygon crossings in the result that the original did not have
  int new_subpixel_loops = 0;  ///< loops under kSubpixelLoopPx the original did not have
  int new_sharp_turns = 0;  ///< sharp turns of the result not within kSameTurnPx of the original's
  std::vector<Point2> sharp_turn_points;  ///< where (the new ones)
  double worst_full_error = 0.0;
  double worst_reduced_error = 0.0;
  std::vector<double> full_errors;     ///< relative amplitude error of every rated full lobe
  std::vector<std::string> failures;   ///< one line per lobe outside the tolerance or wrong count
  std::vector<Point2> failure_points;  ///< where (the lobe's extreme; a wrong count: none)
  double median_full_error() const;
};

GlyphCheck checkGlyph(const DiffusionCurveImage& original, const DiffusionCurveImage& modified,
                      const std::vector<CurveWaveReport>& reports, const WaveSpec& spec,
                      double px_per_mm);

void add(GlyphCheck& total, const GlyphCheck& part);

}  // namespace measure
}  // namespace pacemod
}  // namespace vicc_glyphs
