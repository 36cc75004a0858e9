#include "vicc_glyphs/pacemod/periodic_waves.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>

#include "vicc_glyphs/bspline/arc_length.hpp"
#include "vicc_glyphs/bspline/spline_diffusion_curve.hpp"
#include "vicc_glyphs/pacemod/contour_teeth.hpp"
#include "vicc_glyphs/pacemod/contour_waves.hpp"
#include "vicc_glyphs/pacemod/polygon_crossings.hpp"
#include "vicc_glyphs/pacemod/polyline.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

constexpr double kMinQuarterPeriodPx = 0.5;
constexpr double kNoCap = 1e300;
constexpr int kSamplesPerSpan = 16;  // as dense as the bench's polygon check
// Bucket size of the crossing search, px: high-frequency waves put hundreds of their dense
// samples into an 8 px cell, and each bucket's pairs are tested.
constexpr double kCrossingCellPx = 2.0;

// A curve being waved: its spline form, arc-length table, current wave and amplitude caps.
struct WavedContour {
  bspline::SplineDiffusionCurve spline;
  std::unique_ptr<bspline::ArcLengthTable> table;
  std::unique_ptr<ContourFrame> frame;  ///< built once, the same for every repair round
  std::unique_ptr<ContourWave> wave;
  std::vector<double> caps;
  CurveWaveReport report;
};

struct Context {
  const WaveSpec& spec;
  double px_per_mm;
  const SkeletonGuard* guard;
};

void checkArguments(const DiffusionCurveImage& image, const std::vector<int>& curves,
                    const WaveSpec& spec, double glyph_size_mm) {
  const std::string problem = validate(spec);
  if (!problem.empty()) throw std::invalid_argument(problem);
  if (!std::isfinite(glyph_size_mm) || !(glyph_size_mm > 0.0)) {
    throw std::invalid_argument("glyph_size_mm must be a finite number > 0");
  }
  const std::string too_large = checkDisplacement("amplitude_mm", spec.amplitude_mm, glyph_size_mm);
  if (!too_large.empty()) throw std::invalid_argument(too_large);
  if (image.width < 1) throw std::invalid_argument("image has no width");
  for (int index : curves) {
    if (index < 0 || index >= static_cast<int>(image.curves.size())) {
      throw std::invalid_argument("curve index " + std::to_string(index) + " out of range");
    }
  }
}

void build(WavedContour& contour, const Context& context) {
  if (!contour.frame) {
    contour.frame = std::make_unique<ContourFrame>(contourFrame(
        contour.spline.geometry, *contour.table, context.spec.waveform, contour.report.wave_count));
  }
  contour.wave = std::make_unique<ContourWave>(
      modifyContour(*contour.frame, contour.spline.geometry, *contour.table,
                    context.spec.amplitude_mm * context.px_per_mm, context.guard, contour.caps));
  // No cap until the polygon check sets one (capAround halves the amplitude applied).
  if (contour.caps.empty()) contour.caps.assign(contour.wave->guarded.size(), kNoCap);
}

// Null when the curve stays unchanged (the report says why).
std::unique_ptr<WavedContour> prepare(const DiffusionCurve& curve, int index,
                                      const Context& context, CurveWaveReport& report) {
  report.curve = index;
  report.requested_amplitude_mm = context.spec.amplitude_mm;
  if (curve.segmentCount() < 1 ||
      (curve.control_points.front() - curve.control_points.back()).norm() > 1e-6) {
    report.skipped = "not a closed curve";
    return nullptr;
  }
  std::unique_ptr<WavedContour> contour(new WavedContour{
      bspline::toSplineDiffusionCurve(withoutTeeth(curve)), nullptr, nullptr, nullptr, {}, report});
  contour->table = std::make_unique<bspline::ArcLengthTable>(contour->spline.geometry);
  const double length = contour->table->totalLength();
  report.arc_length_mm = length / context.px_per_mm;
  report.requested_waves = context.spec.waves_per_mm * report.arc_length_mm;
  report.wave_count = wholeWaveCount(context.spec.waves_per_mm, report.arc_length_mm);
  if (report.wave_count == 0) {
    report.skipped = "fewer than half a wave fits on the contour";
    return nullptr;
  }
  if (length / (4.0 * report.wave_count) < kMinQuarterPeriodPx) {
    throw std::invalid_argument("waves_per_mm too high for curve " + std::to_string(index) +
                                ": a quarter period would be shorter than half a pixel");
  }
  contour->report = report;
  build(*contour, context);
  return contour;
}

// Polyline of the wave's spline with the spline parameter (= original arc length) per point.
Polyline sampleWave(const ContourWave& wave, std::vector<double>& parameters) {
  return wave.curve.sampleSpans(kSamplesPerSpan, parameters);
}

// Halves the caps of the knot points within half a period of arc length `u` (cyclically), or
// sets them to 0 in the last round. A crossing can persist with every knot point of that window
// already at 0: the curve between knot points (a neighbouring lobe's flank overshooting into a
// thin spike, the swallowtail at a sharp icon corner) makes it. Then the window widens by half
// periods until it reaches knot points with amplitude left, so that repeated rounds flatten the
// contour around the crossing outward until the crossing is gone (at worst the whole contour).
void capAround(WavedContour& contour, double u, bool last_round) {
  const WaveLayout& layout = contour.wave->layout;
  const double half_period = 0.5 * layout.length / layout.wave_count;
  auto applied = [&](std::size_t i) {
    return std::min(contour.caps[i], contour.wave->guarded[i].amplitude);
  };
  double window = half_period;
  for (;;) {
    bool reducible = false;
    for (std::size_t i = 0; i < layout.peaks.size(); ++i) {
      reducible |= cyclicDistance(layout.peaks[i].arc_length, u, layout.length) <= window &&
                   applied(i) > 0.0;
    }
    if (reducible || window >= 0.5 * layout.length) break;
    window += half_period;
  }
  for (std::size_t i = 0; i < layout.peaks.size(); ++i) {
    if (cyclicDistance(layout.peaks[i].arc_length, u, layout.length) > window) continue;
    contour.caps[i] = last_round ? 0.0 : std::min(contour.caps[i], 0.5 * applied(i));
  }
  contour.caps.back() = contour.caps.front() = std::min(contour.caps.front(), contour.caps.back());
}

// The crossings that the original contours have themselves: contours that touch (two circles
// side by side) cross as polygons at the touching point, and a wave kept flat there keeps the
// original's crossing. Per pair of lines (a < b) the points.
class InheritedCrossings {
 public:
  InheritedCrossings(const DiffusionCurveImage& image, CrossingFinder& finder) {
    std::vector<Polyline> lines;
    for (const DiffusionCurve& curve : image.curves) lines.push_back(sampleCurve(curve, 16));
    for (const Crossing& crossing : finder.find(lines, kCrossingCellPx)) {
      points_[{crossing.a.line, crossing.b.line}].push_back(crossingPoint(lines, crossing));
    }
  }

  // Whether `crossing` of `lines` lies where the originals of its two lines cross.
  bool contains(const std::vector<Polyline>& lines, const Crossing& crossing) const {
    const auto found = points_.find({crossing.a.line, crossing.b.line});
    if (found == points_.end()) return false;
    const Point2 point = crossingPoint(lines, crossing);
    return std::any_of(found->second.begin(), found->second.end(), [&](const Point2& original) {
      return (original - point).norm() <= kSamePlacePx;
    });
  }

 private:
  // Sampled differently (the wave's spans, the original's segments), the same crossing moves
  // by far less than this; a wave's own crossing lies a lobe's amplitude (1 px or more) away.
  static constexpr double kSamePlacePx = 0.25;
  std::map<std::pair<int, int>, std::vector<Point2>> points_;
};

// The polygon check after the skeleton guard; returns the crossings left per image curve
// (those the original contours have themselves neither repaired nor counted).
std::map<int, int> repairCrossings(const DiffusionCurveImage& image,
                                   std::map<int, std::unique_ptr<WavedContour>>& waved,
                                   const Context& context) {
  std::map<int, int> left;
  std::optional<InheritedCrossings> inherited;  // built at the first crossing (most have none)
  CrossingFinder finder;
  // Sampled once; a round samples again only the contours it rebuilt.
  std::vector<Polyline> lines;
  std::vector<std::vector<double>> parameters(image.curves.size());
  for (int i = 0; i < static_cast<int>(image.curves.size()); ++i) {
    const auto found = waved.find(i);
    lines.push_back(found != waved.end() ? sampleWave(*found->second->wave, parameters[i])
                                         : sampleCurve(image.curves[i], 16));
  }
  const int last_round = kMaxRepairRounds + kMaxFlatteningRounds;
  for (int round = 0; round <= last_round; ++round) {
    const std::vector<Crossing> crossings = finder.find(lines, kCrossingCellPx);
    std::map<int, bool> changed;
    left.clear();
    for (const Crossing& crossing : crossings) {
      if (!inherited) inherited.emplace(image, finder);
      if (inherited->contains(lines, crossing)) continue;
      for (const SegmentRef& side : {crossing.a, crossing.b}) {
        ++left[side.line];
        const auto found = waved.find(side.line);
        if (found == waved.end() || round == last_round) continue;
        capAround(*found->second, parameters[side.line][side.segment],
                  round + 1 >= kMaxRepairRounds);
        changed[side.line] = true;
      }
    }
    if (changed.empty()) break;
    for (const auto& entry : changed) {
      WavedContour& contour = *waved[entry.first];
      build(contour, context);
      lines[entry.first] = sampleWave(*contour.wave, parameters[entry.first]);
    }
  }
  return left;
}

void finishReport(const WavedContour& contour, const Polyline& original, double px_per_mm,
                  CurveWaveReport& report) {
  const ContourWave& wave = *contour.wave;
  double sum = 0.0, low = 1e300, high = 0.0;
  const PolylineDistance distance(original);
  for (double parameter : wave.parameters) {
    const double d = distance(wave.curve.pointAt(parameter)) / px_per_mm;
    sum += d;
    low = std::min(low, d);
    high = std::max(high, d);
  }
  report.knot_points = static_cast<int>(wave.layout.peaks.size());
  report.realised_amplitude_min_mm = low;
  report.realised_amplitude_mean_mm = sum / wave.layout.peaks.size();
  report.realised_amplitude_max_mm = high;
  for (std::size_t i = 0; i + 1 < wave.guarded.size(); ++i) {  // the last repeats the first
    if (wave.guarded[i].reduced || wave.capped[i] || wave.cornered[i]) {
      report.reductions.push_back(
          {wave.layout.peaks[i].arc_length / px_per_mm, wave.guarded[i].amplitude / px_per_mm,
           wave.capped[i] ? "crossing" : (wave.guarded[i].reduced ? "skeleton" : "corner")});
    }
  }
}

template <typename Points>
void toArcLength(Points& points, const bspline::ArcLengthTable& table) {
  for (auto& point : points) point.position = table.lengthAt(point.position);
}

DiffusionCurve wavedCurve(WavedContour& contour) {
  bspline::SplineDiffusionCurve spline = contour.spline;
  toArcLength(spline.left_colors, *contour.table);
  toArcLength(spline.right_colors, *contour.table);
  toArcLength(spline.blur_points, *contour.table);
  spline.geometry = contour.wave->curve;
  return bspline::toDiffusionCurve(spline);
}

}  // namespace

std::vector<CurveWaveReport> applyWaves(DiffusionCurveImage& image,
                                        const std::vector<int>& curves_in, const WaveSpec& spec,
                                        double glyph_size_mm, const WaveOptions& options) {
  checkArguments(image, curves_in, spec, glyph_size_mm);
  std::vector<int> curves = curves_in;
  std::sort(curves.begin(), curves.end());
  curves.erase(std::unique(curves.begin(), curves.end()), curves.end());
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
  const Context context{spec, px_per_mm, guard.get()};
  std::vector<CurveWaveReport> reports(curves.size());
  std::map<int, std::unique_ptr<WavedContour>> waved;
  for (std::size_t k = 0; k < curves.size(); ++k) {
    std::unique_ptr<WavedContour> contour =
        prepare(image.curves[curves[k]], curves[k], context, reports[k]);
    if (contour) waved[curves[k]] = std::move(contour);
  }
  std::map<int, int> left;
  if (options.prevent_self_intersection) left = repairCrossings(image, waved, context);
  for (CurveWaveReport& report : reports) {
    const auto found = waved.find(report.curve);
    if (found == waved.end()) continue;
    report = found->second->report;
    finishReport(*found->second, sampleCurve(image.curves[report.curve], 32), px_per_mm, report);
    report.unresolved_crossings = left.count(report.curve) ? left[report.curve] : 0;
    image.curves[report.curve] = wavedCurve(*found->second);
  }
  return reports;
}

}  // namespace pacemod
}  // namespace vicc_glyphs
