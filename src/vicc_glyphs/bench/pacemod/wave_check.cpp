#include "wave_check.hpp"

#include <algorithm>
#include <cmath>

#include "vicc_glyphs/pacemod/polygon_crossings.hpp"
#include "vicc_glyphs/pacemod/polyline.hpp"
#include "vicc_glyphs/pacemod/wave_layout.hpp"
#include "wave_measurement.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace measure {
namespace {

struct AppliedPeak {
  double arc_px;
  int sign;
  double amplitude_px;
};

// The knot points of the contour with the amplitude the guard let through.
std::vector<AppliedPeak> appliedPeaks(const CurveWaveReport& report, const WaveSpec& spec,
                                      double px_per_mm) {
  const WaveLayout layout =
      waveLayout(spec.waveform, report.wave_count, report.arc_length_mm * px_per_mm);
  std::vector<AppliedPeak> peaks;
  for (const WavePeak& peak : layout.peaks) {
    double amplitude = spec.amplitude_mm * px_per_mm;
    for (const PeakReduction& r : report.reductions) {
      if (std::abs(r.arc_length_mm * px_per_mm - peak.arc_length) < 1e-6) {
        amplitude = r.allowed_mm * px_per_mm;
      }
    }
    peaks.push_back({peak.arc_length, peak.sign, amplitude});
  }
  // The closing knot point repeats the first one.
  if (peaks.size() > 1) peaks.back().amplitude_px = peaks.front().amplitude_px;
  return peaks;
}

bool inLobe(const Lobe& lobe, double arc) {
  return lobe.arc_begin <= lobe.arc_end ? (arc >= lobe.arc_begin && arc <= lobe.arc_end)
                                        : (arc >= lobe.arc_begin || arc <= lobe.arc_end);
}

int crossings(const DiffusionCurveImage& image) {
  std::vector<Polyline> lines;
  for (const DiffusionCurve& curve : image.curves) lines.push_back(sampleCurve(curve, 16));
  return static_cast<int>(findCrossings(lines).size());
}

void checkContour(const Polyline& original, const Polyline& modified, const CurveWaveReport& report,
                  const WaveSpec& spec, double px_per_mm, GlyphCheck& check) {
  const double amplitude_px = spec.amplitude_mm * px_per_mm;
  const std::vector<AppliedPeak> peaks = appliedPeaks(report, spec, px_per_mm);
  const bool flattened = std::any_of(peaks.begin(), peaks.end(), [&](const AppliedPeak& p) {
    return p.amplitude_px < 0.5 * amplitude_px;
  });
  const ContourMeasure measured = measureContour(original, modified, 0.25 * amplitude_px);
  ++check.contours;
  check.reduced_peaks += static_cast<int>(report.reductions.size());
  if (flattened) {
    ++check.flattened_contours;
  } else {
    ++check.count_checked;
    check.count_ok += measured.outward == report.wave_count && measured.inward == report.wave_count;
  }
  for (const Lobe& lobe : measured.lobes) {
    double expected = 0.0;
    for (const AppliedPeak& peak : peaks) {
      if (peak.sign == lobe.sign && inLobe(lobe, peak.arc_px)) {
        expected = std::max(expected, peak.amplitude_px);
      }
    }
    if (expected < kMinCheckedAmplitudePx) continue;
    const double error = std::abs(lobe.extreme_px - expected) / expected;
    ++check.lobes_checked;
    check.lobes_ok += error <= kAmplitudeTolerance;
    check.worst_error = std::max(check.worst_error, error);
    check.errors.push_back(error);
  }
}

}  // namespace

double GlyphCheck::median_error() const {
  if (errors.empty()) return 0.0;
  std::vector<double> sorted = errors;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  return sorted[sorted.size() / 2];
}

GlyphCheck checkGlyph(const DiffusionCurveImage& original, const DiffusionCurveImage& modified,
                      const std::vector<CurveWaveReport>& reports, const WaveSpec& spec,
                      double px_per_mm) {
  GlyphCheck check;
  for (const CurveWaveReport& report : reports) {
    if (report.wave_count < 1) continue;
    checkContour(sampleCurve(original.curves[report.curve], 32),
                 sampleCurve(modified.curves[report.curve], 16), report, spec, px_per_mm, check);
  }
  check.new_crossings = std::max(0, crossings(modified) - crossings(original));
  return check;
}

void add(GlyphCheck& total, const GlyphCheck& part) {
  total.contours += part.contours;
  total.count_checked += part.count_checked;
  total.count_ok += part.count_ok;
  total.flattened_contours += part.flattened_contours;
  total.lobes_checked += part.lobes_checked;
  total.lobes_ok += part.lobes_ok;
  total.reduced_peaks += part.reduced_peaks;
  total.new_crossings += part.new_crossings;
  total.worst_error = std::max(total.worst_error, part.worst_error);
  total.errors.insert(total.errors.end(), part.errors.begin(), part.errors.end());
}

}  // namespace measure
}  // namespace pacemod
}  // namespace vicc_glyphs
