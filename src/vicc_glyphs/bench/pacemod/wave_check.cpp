#include "wave_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

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

// The lobes the applied amplitudes should produce: runs of knot points of one sign (cyclic)
// form one lobe; a run whose largest amplitude is below kInvisible of the requested one leaves
// no lobe above the measuring threshold, so its neighbours merge. Returns {outward, inward}, or
// {-1, -1} when a run lies between kInvisible and kVisible (then a count is not decidable).
constexpr double kInvisible = 0.15;
constexpr double kVisible = 0.6;

std::pair<int, int> expectedLobes(const std::vector<AppliedPeak>& peaks, double requested) {
  std::vector<std::pair<int, double>> runs;             // sign, largest amplitude
  for (std::size_t i = 0; i + 1 < peaks.size(); ++i) {  // the last repeats the first
    if (runs.empty() || runs.back().first != peaks[i].sign) runs.push_back({peaks[i].sign, 0.0});
    runs.back().second = std::max(runs.back().second, peaks[i].amplitude_px);
  }
  if (runs.size() > 1 && runs.front().first == runs.back().first) {
    runs.front().second = std::max(runs.front().second, runs.back().second);
    runs.pop_back();
  }
  std::vector<int> visible;
  for (const auto& run : runs) {
    if (run.second >= kVisible * requested) {
      visible.push_back(run.first);
    } else if (run.second > kInvisible * requested) {
      return {-1, -1};
    }
  }
  std::vector<int> merged;
  for (int sign : visible) {
    if (merged.empty() || merged.back() != sign) merged.push_back(sign);
  }
  if (merged.size() > 1 && merged.front() == merged.back()) merged.pop_back();
  const int outward = static_cast<int>(std::count(merged.begin(), merged.end(), 1));
  return {outward, static_cast<int>(merged.size()) - outward};
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
  const std::pair<int, int> expected_lobes = expectedLobes(peaks, amplitude_px);
  const ContourMeasure measured = measureContour(original, modified, 0.25 * amplitude_px);
  ++check.contours;
  check.reduced_peaks += static_cast<int>(report.reductions.size());
  if (expected_lobes.first < 0) {
    ++check.flattened_contours;
  } else {
    ++check.count_checked;
    check.count_ok +=
        measured.outward == expected_lobes.first && measured.inward == expected_lobes.second;
    check.contours_with_all_waves += expected_lobes.first == report.wave_count;
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
    if (error > kAmplitudeTolerance) {
      char line[160];
      std::snprintf(line, sizeof line,
                    "curve %d, %s lobe at arc %.1f-%.1f px: expected %.2f px, measured %.2f px",
                    report.curve, lobe.sign > 0 ? "outward" : "inward", lobe.arc_begin,
                    lobe.arc_end, expected, lobe.extreme_px);
      check.failures.push_back(line);
    }
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
  total.contours_with_all_waves += part.contours_with_all_waves;
  total.flattened_contours += part.flattened_contours;
  total.lobes_checked += part.lobes_checked;
  total.lobes_ok += part.lobes_ok;
  total.reduced_peaks += part.reduced_peaks;
  total.new_crossings += part.new_crossings;
  total.worst_error = std::max(total.worst_error, part.worst_error);
  total.errors.insert(total.errors.end(), part.errors.begin(), part.errors.end());
  total.failures.insert(total.failures.end(), part.failures.begin(), part.failures.end());
}

}  // namespace measure
}  // namespace pacemod
}  // namespace vicc_glyphs
