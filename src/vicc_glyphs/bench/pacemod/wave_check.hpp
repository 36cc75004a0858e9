#pragma once
// The per-glyph checks of the PACEMOD bench and its GoogleTest subset: wave counts, lobe
// amplitudes against the applied amplitudes, and new polygon crossings.

#include <string>
#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"
#include "vicc_glyphs/pacemod/periodic_waves.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace measure {

constexpr double kAmplitudeTolerance = 0.10;
/// Lobes whose expected amplitude is below this many pixels are not checked relatively.
constexpr double kMinCheckedAmplitudePx = 0.5;

struct GlyphCheck {
  int contours = 0;  ///< modified contours (wave count >= 1)
  /// contours whose lobe count is decidable: every run of same-sign knot points kept >= 60 %
  /// or was cut below 15 % of the amplitude by self-intersection prevention
  int count_checked = 0;
  /// measured outward and inward lobes == those expected from the applied amplitudes (the wave
  /// count, less lobes that self-intersection prevention removed)
  int count_ok = 0;
  int contours_with_all_waves = 0;  ///< decidable contours where no lobe was removed
  int flattened_contours = 0;       ///< not decidable (a run between 15 % and 60 %)
  int lobes_checked = 0;
  int lobes_ok = 0;       ///< |extreme - expected| <= 10 % of expected
  int reduced_peaks = 0;  ///< knot points the skeleton guard shortened
  int new_crossings = 0;  ///< polygon crossings in the result that the original did not have
  double worst_error = 0.0;
  std::vector<double> errors;         ///< relative amplitude error of every checked lobe
  std::vector<std::string> failures;  ///< one line per lobe outside the tolerance
  double median_error() const;
};

GlyphCheck checkGlyph(const DiffusionCurveImage& original, const DiffusionCurveImage& modified,
                      const std::vector<CurveWaveReport>& reports, const WaveSpec& spec,
                      double px_per_mm);

void add(GlyphCheck& total, const GlyphCheck& part);

}  // namespace measure
}  // namespace pacemod
}  // namespace vicc_glyphs
