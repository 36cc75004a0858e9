#include "vicc_glyphs/pacemod/periodic_waves.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "vicc_glyphs/bspline/arc_length.hpp"
#include "vicc_glyphs/bspline/spline_diffusion_curve.hpp"
#include "vicc_glyphs/pacemod/contour_waves.hpp"
#include "vicc_glyphs/pacemod/polyline.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

constexpr double kMinQuarterPeriodPx = 0.5;

template <typename Points>
void toArcLength(Points& points, const bspline::ArcLengthTable& table) {
  for (auto& point : points) point.position = table.lengthAt(point.position);
}

void checkArguments(const DiffusionCurveImage& image, const std::vector<int>& curves,
                    const WaveSpec& spec, double glyph_size_mm) {
  const std::string problem = validate(spec);
  if (!problem.empty()) throw std::invalid_argument(problem);
  if (!std::isfinite(glyph_size_mm) || !(glyph_size_mm > 0.0)) {
    throw std::invalid_argument("glyph_size_mm must be a finite number > 0");
  }
  if (image.width < 1) throw std::invalid_argument("image has no width");
  for (int index : curves) {
    if (index < 0 || index >= static_cast<int>(image.curves.size())) {
      throw std::invalid_argument("curve index " + std::to_string(index) + " out of range");
    }
  }
}

void measureRealised(const ContourWave& wave, const Polyline& original, double px_per_mm,
                     CurveWaveReport& report) {
  double sum = 0.0, low = 1e300, high = 0.0;
  for (const WavePeak& peak : wave.layout.peaks) {
    const double d = distanceToPolyline(wave.curve.pointAt(peak.arc_length), original) / px_per_mm;
    sum += d;
    low = std::min(low, d);
    high = std::max(high, d);
  }
  report.knot_points = static_cast<int>(wave.layout.peaks.size());
  report.realised_amplitude_min_mm = low;
  report.realised_amplitude_mean_mm = sum / wave.layout.peaks.size();
  report.realised_amplitude_max_mm = high;
  for (std::size_t i = 0; i + 1 < wave.guarded.size(); ++i) {  // the last repeats the first
    if (wave.guarded[i].reduced) {
      report.reductions.push_back(
          {wave.layout.peaks[i].arc_length / px_per_mm, wave.guarded[i].amplitude / px_per_mm});
    }
  }
}

CurveWaveReport modifyCurve(DiffusionCurve& curve, int index, const WaveSpec& spec,
                            double px_per_mm, const SkeletonGuard* guard) {
  CurveWaveReport report;
  report.curve = index;
  report.requested_amplitude_mm = spec.amplitude_mm;
  if (curve.segmentCount() < 1 ||
      (curve.control_points.front() - curve.control_points.back()).norm() > 1e-6) {
    report.skipped = "not a closed curve";
    return report;
  }
  bspline::SplineDiffusionCurve spline = bspline::toSplineDiffusionCurve(curve);
  const bspline::ArcLengthTable table(spline.geometry);
  const double length = table.totalLength();
  report.arc_length_mm = length / px_per_mm;
  report.requested_waves = spec.waves_per_mm * report.arc_length_mm;
  report.wave_count = wholeWaveCount(spec.waves_per_mm, report.arc_length_mm);
  if (report.wave_count == 0) {
    report.skipped = "fewer than half a wave fits on the contour";
    return report;
  }
  if (length / (4.0 * report.wave_count) < kMinQuarterPeriodPx) {
    throw std::invalid_argument("waves_per_mm too high for curve " + std::to_string(index) +
                                ": a quarter period would be shorter than half a pixel");
  }
  const ContourWave wave = modifyContour(spline.geometry, table, spec.waveform, report.wave_count,
                                         spec.amplitude_mm * px_per_mm, guard);
  measureRealised(wave, sampleCurve(curve, 32), px_per_mm, report);
  toArcLength(spline.left_colors, table);
  toArcLength(spline.right_colors, table);
  toArcLength(spline.blur_points, table);
  spline.geometry = wave.curve;
  curve = bspline::toDiffusionCurve(spline);
  return report;
}

}  // namespace

std::vector<CurveWaveReport> applyWaves(DiffusionCurveImage& image, const std::vector<int>& curves,
                                        const WaveSpec& spec, double glyph_size_mm,
                                        const WaveOptions& options) {
  checkArguments(image, curves, spec, glyph_size_mm);
  const double px_per_mm = image.width / glyph_size_mm;
  std::unique_ptr<NearestCurvePoint> field;
  std::unique_ptr<SkeletonGuard> guard;
  if (options.prevent_self_intersection && !image.curves.empty()) {
    std::vector<Polyline> lines;
    for (const DiffusionCurve& curve : image.curves) lines.push_back(sampleCurve(curve, 16));
    field =
        std::make_unique<NearestCurvePoint>(lines, image.width, std::max(image.height, 1),
                                            options.field_grid_scale, options.feature_transform);
    guard = std::make_unique<SkeletonGuard>(*field, options.skeleton_offset_mm * px_per_mm);
  }
  std::vector<CurveWaveReport> reports;
  for (int index : curves) {
    reports.push_back(modifyCurve(image.curves[index], index, spec, px_per_mm, guard.get()));
  }
  return reports;
}

}  // namespace pacemod
}  // namespace vicc_glyphs
