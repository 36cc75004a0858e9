#include "wave_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "vicc_glyphs/dci/flattening.hpp"
#include "vicc_glyphs/pacemod/polygon_crossings.hpp"
#include "vicc_glyphs/pacemod/polyline.hpp"
#include "vicc_glyphs/pacemod/wave_layout.hpp"
#include "wave_measurement.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace measure {
namespace {

// Lobes find their knot points within this arc length (px) of their ends.
constexpr double kLobeEndTolerancePx = 0.5;

struct AppliedPeak {
  double arc;  ///< fraction of the contour's length
  int sign;
  double amplitude_px;
  bool reduced;
};

// The knot points of the contour with the amplitude self-intersection prevention let through.
std::vector<AppliedPeak> appliedPeaks(const CurveWaveReport& report, const WaveSpec& spec,
                                      double px_per_mm) {
  const double length = report.arc_length_mm * px_per_mm;
  const WaveLayout layout = waveLayout(spec.waveform, report.wave_count, length);
  std::vector<AppliedPeak> peaks;
  for (const WavePeak& peak : layout.peaks) {
    AppliedPeak applied{peak.arc_length / length, peak.sign, spec.amplitude_mm * px_per_mm, false};
    for (const PeakReduction& r : report.reductions) {
      if (std::abs(r.arc_length_mm * px_per_mm - peak.arc_length) < 1e-6) {
        applied.amplitude_px = r.allowed_mm * px_per_mm;
        applied.reduced = true;
      }
    }
    peaks.push_back(applied);
  }
  // The closing knot point repeats the first one.
  if (peaks.size() > 1) {
    peaks.back().amplitude_px = peaks.front().amplitude_px;
    peaks.back().reduced = peaks.front().reduced;
  }
  return peaks;
}

// The amplitude applied around `arc` (fraction): linear between the enclosing knot points.
double envelope(const std::vector<AppliedPeak>& peaks, double arc) {
  const auto next = std::upper_bound(peaks.begin(), peaks.end(), arc,
                                     [](double a, const AppliedPeak& p) { return a < p.arc; });
  if (next == peaks.begin()) return peaks.front().amplitude_px;
  if (next == peaks.end()) return peaks.back().amplitude_px;
  const AppliedPeak& before = *(next - 1);
  const double t = next->arc > before.arc ? (arc - before.arc) / (next->arc - before.arc) : 0.0;
  return (1.0 - t) * before.amplitude_px + t * next->amplitude_px;
}

// The lobes the applied amplitudes should produce: runs of knot points of one sign (cyclic)
// form one lobe; a run below kInvisiblePx leaves none, so its neighbours merge. Returns
// {outward, inward}, or {-1, -1} when a run lies between kInvisiblePx and kVisiblePx.
std::pair<int, int> expectedLobes(const std::vector<AppliedPeak>& peaks) {
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
    if (run.second >= kVisiblePx) {
      visible.push_back(run.first);
    } else if (run.second >= kInvisiblePx) {
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

bool inLobe(const Lobe& lobe, double arc, double tolerance) {
  const double begin = lobe.arc_begin - tolerance, end = lobe.arc_end + tolerance;
  if (lobe.arc_begin > lobe.arc_end) return arc >= begin || arc <= end;  // over the start
  for (double shifted : {arc, arc - 1.0, arc + 1.0}) {
    if (shifted >= begin && shifted <= end) return true;
  }
  return false;
}

// Length of the loop that a crossing of one closed polyline with itself cuts off (the shorter
// way round between the two crossing segments); infinite for two different polylines.
double loopLength(const std::vector<Polyline>& lines, const Crossing& crossing) {
  if (crossing.a.line != crossing.b.line) return std::numeric_limits<double>::infinity();
  const Polyline& line = lines[crossing.a.line];
  double inner = 0.0, total = 0.0;
  for (int i = 0; i + 1 < static_cast<int>(line.size()); ++i) {
    const double step = (line[i + 1] - line[i]).norm();
    total += step;
    if (i > crossing.a.segment && i < crossing.b.segment) inner += step;
  }
  return std::min(inner, total - inner);
}

struct CrossingCount {
  int drawn = 0;           ///< of the polylines the renderer draws
  int dense = 0;           ///< at 16 points per segment, around loops of kSubpixelLoopPx or more
  int subpixel_loops = 0;  ///< at 16 points per segment, around shorter loops
};

CrossingCount crossings(const DiffusionCurveImage& image) {
  CrossingCount count;
  std::vector<Polyline> drawn, dense;
  for (const DiffusionCurve& curve : image.curves) {
    drawn.push_back(flattenCurve(curve));
    dense.push_back(sampleCurve(curve, 16));
  }
  count.drawn = static_cast<int>(findCrossings(drawn).size());
  for (const Crossing& crossing : findCrossings(dense)) {
    ++(loopLength(dense, crossing) < kSubpixelLoopPx ? count.subpixel_loops : count.dense);
  }
  return count;
}

// Every place where a step of a curve's polyline turns by more than kSharpTurnDegrees against
// the previous step (steps shorter than 1e-6 px skipped; a closed curve's seam included).
std::vector<Point2> sharpTurns(const DiffusionCurveImage& image) {
  const double limit = std::cos(kSharpTurnDegrees * M_PI / 180.0);
  std::vector<Point2> turns;
  for (const DiffusionCurve& curve : image.curves) {
    const Polyline line = sampleCurve(curve, 16);
    std::vector<std::pair<Point2, Point2>> steps;  // start point, unit direction
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
      const Point2 d = line[i + 1] - line[i];
      if (d.norm() > 1e-6) steps.push_back({line[i], d.normalized()});
    }
    const bool closed = line.size() > 2 && (line.front() - line.back()).norm() < 1e-9;
    for (std::size_t k = closed ? 0 : 1; k < steps.size(); ++k) {
      const Point2& before = (k == 0 ? steps.back() : steps[k - 1]).second;
      if (before.dot(steps[k].second) < limit) turns.push_back(steps[k].first);
    }
  }
  return turns;
}

std::string lobeText(const CurveWaveReport& report, const Lobe& lobe, double length_px) {
  char text[160];
  std::snprintf(text, sizeof text, "curve %d, %s lobe at arc %.1f-%.1f px (%.1f, %.1f)",
                report.curve, lobe.sign > 0 ? "outward" : "inward", lobe.arc_begin * length_px,
                lobe.arc_end * length_px, lobe.extreme_point.x(), lobe.extreme_point.y());
  return text;
}

// Rates every lobe against the largest amplitude applied to its knot points of its sign.
void rateLobes(const ContourMeasure& measured, const std::vector<AppliedPeak>& peaks,
               const CurveWaveReport& report, double length_px, bool count_ok, GlyphCheck& check) {
  for (const Lobe& lobe : measured.lobes) {
    double expected = 0.0;
    bool any = false, reduced = false;
    for (const AppliedPeak& peak : peaks) {
      if (peak.sign != lobe.sign || !inLobe(lobe, peak.arc, kLobeEndTolerancePx / length_px)) {
        continue;
      }
      any = true;
      reduced |= peak.reduced;
      expected = std::max(expected, peak.amplitude_px);
    }
    char line[256];
    if (!any) {
      if (count_ok) continue;
      std::snprintf(line, sizeof line, "%s without a knot point: measured %.2f px",
                    lobeText(report, lobe, length_px).c_str(), lobe.extreme_px);
      check.failures.push_back(line);
      check.failure_points.push_back(lobe.extreme_point);
      continue;
    }
    if (expected < kMinCheckedAmplitudePx) continue;
    const double error = std::abs(lobe.extreme_px - expected) / expected;
    const bool ok = error <= kAmplitudeTolerance;
    if (reduced) {
      ++check.reduced_lobes;
      check.reduced_lobes_ok += ok;
      check.worst_reduced_error = std::max(check.worst_reduced_error, error);
    } else {
      ++check.full_lobes;
      check.full_lobes_ok += ok;
      check.worst_full_error = std::max(check.worst_full_error, error);
      check.full_errors.push_back(error);
    }
    if (!ok) {
      std::snprintf(line, sizeof line, "%s%s: expected %.2f px, measured %.2f px",
                    lobeText(report, lobe, length_px).c_str(), reduced ? " (reduced)" : "",
                    expected, lobe.extreme_px);
      check.failures.push_back(line);
      check.failure_points.push_back(lobe.extreme_point);
    }
  }
}

void checkContour(const Polyline& original, const Polyline& modified, const CurveWaveReport& report,
                  const WaveSpec& spec, double px_per_mm, GlyphCheck& check) {
  const std::vector<AppliedPeak> peaks = appliedPeaks(report, spec, px_per_mm);
  const double length_px = report.arc_length_mm * px_per_mm;
  const ContourMeasure measured = measureContour(original, modified, [&peaks](double arc) {
    return std::max(kMinLobeThresholdPx, kLobeThreshold * envelope(peaks, arc));
  });
  ++check.contours;
  check.reduced_peaks += static_cast<int>(report.reductions.size());
  for (const PeakReduction& r : report.reductions) check.crossing_peaks += r.reason == "crossing";
  std::pair<int, int> expected{report.wave_count, report.wave_count};
  if (report.reductions.empty()) {
    ++check.unreduced_contours;
  } else {
    expected = expectedLobes(peaks);
    if (expected.first < 0) {
      ++check.reduced_undecidable;
    } else {
      ++check.reduced_decidable;
    }
  }
  const bool decidable = expected.first >= 0;
  const bool count_ok =
      decidable && measured.outward == expected.first && measured.inward == expected.second;
  if (count_ok) (report.reductions.empty() ? check.unreduced_count_ok : check.reduced_count_ok)++;
  if (decidable && !count_ok) {
    char line[224];
    std::snprintf(line, sizeof line,
                  "curve %d: %d outward + %d inward lobes, expected %d + %d (%d waves%s)",
                  report.curve, measured.outward, measured.inward, expected.first, expected.second,
                  report.wave_count, report.reductions.empty() ? "" : ", some knot points reduced");
    check.failures.push_back(line);
  }
  rateLobes(measured, peaks, report, length_px, count_ok || !decidable, check);
}

}  // namespace

double GlyphCheck::median_full_error() const {
  if (full_errors.empty()) return 0.0;
  std::vector<double> sorted = full_errors;
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
  const CrossingCount before_crossings = crossings(original), after = crossings(modified);
  check.new_crossings =
      std::max({0, after.drawn - before_crossings.drawn, after.dense - before_crossings.dense});
  check.new_subpixel_loops = std::max(0, after.subpixel_loops - before_crossings.subpixel_loops);
  const std::vector<Point2> before = sharpTurns(original);
  for (const Point2& turn : sharpTurns(modified)) {
    const bool known = std::any_of(before.begin(), before.end(), [&](const Point2& old) {
      return (old - turn).norm() <= kSameTurnPx;
    });
    if (!known) check.sharp_turn_points.push_back(turn);
  }
  check.new_sharp_turns = static_cast<int>(check.sharp_turn_points.size());
  return check;
}

void add(GlyphCheck& total, const GlyphCheck& part) {
  total.contours += part.contours;
  total.unreduced_contours += part.unreduced_contours;
  total.unreduced_count_ok += part.unreduced_count_ok;
  total.reduced_decidable += part.reduced_decidable;
  total.reduced_count_ok += part.reduced_count_ok;
  total.reduced_undecidable += part.reduced_undecidable;
  total.full_lobes += part.full_lobes;
  total.full_lobes_ok += part.full_lobes_ok;
  total.reduced_lobes += part.reduced_lobes;
  total.reduced_lobes_ok += part.reduced_lobes_ok;
  total.reduced_peaks += part.reduced_peaks;
  total.crossing_peaks += part.crossing_peaks;
  total.new_crossings += part.new_crossings;
  total.new_subpixel_loops += part.new_subpixel_loops;
  total.new_sharp_turns += part.new_sharp_turns;
  total.worst_full_error = std::max(total.worst_full_error, part.worst_full_error);
  total.worst_reduced_error = std::max(total.worst_reduced_error, part.worst_reduced_error);
  total.full_errors.insert(total.full_errors.end(), part.full_errors.begin(),
                           part.full_errors.end());
  total.failures.insert(total.failures.end(), part.failures.begin(), part.failures.end());
  total.failure_points.insert(total.failure_points.end(), part.failure_points.begin(),
                              part.failure_points.end());
}

}  // namespace measure
}  // namespace pacemod
}  // namespace vicc_glyphs
