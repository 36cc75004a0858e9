#include "vicc_glyphs/pacemod/periodic_waves.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>

#include "vicc_glyphs/bspline/arc_length.hpp"
#include "vicc_glyphs/bspline/spline_diffusion_curve.hpp"
#include "vicc_glyphs/dci/flattening.hpp"
#include "vicc_glyphs/pacemod/contour_teeth.hpp"
#include "vicc_glyphs/pacemod/contour_waves.hpp"
#include "vicc_glyphs/pacemod/polygon_crossings.hpp"
#include "vicc_glyphs/pacemod/polyline.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

constexpr double kMinQuarterPeriodPx = 0.5;
constexpr double kNoCap = 1e300;

// A curve being waved: its spline form, arc-length table, current wave and amplitude caps.
struct WavedContour {
  bspline::SplineDiffusionCurve spline;
  std::unique_ptr<bspline::ArcLengthTable> table;
  std::unique_ptr<ContourFrame> frame;  ///< built once, the same for every repair round
  std::unique_ptr<ContourWave> wave;
  std::vector<double> caps;
  GuardVerdicts verdicts;  ///< kept between repair rounds: only changed caps are judged again
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
                    context.spec.amplitude_mm * context.px_per_mm, context.guard, contour.caps,
                    &contour.verdicts));
  // No cap until the polygon check sets one (capAround halves the amplitude applied).
  if (contour.caps.empty()) contour.caps.assign(contour.wave->guarded.size(), kNoCap);
}

// Only closed contours take waves.
bool closedContour(const DiffusionCurve& curve) {
  return curve.segmentCount() >= 1 &&
         (curve.control_points.front() - curve.control_points.back()).norm() <= 1e-6;
}

// The image's curves as the waves take them: the closed contours among `waved` (sorted
// indices) without their sub-pixel teeth, the others as they are. The skeleton guard must find a
// knot point on its own contour as waved, not up to a few tenths of a pixel in front of it: 16
// pieces per Bezier segment and the contours with their teeth cut some 1 px waves to 0 that way.
std::vector<DiffusionCurve> curvesAsWaved(const DiffusionCurveImage& image,
                                          const std::vector<int>& waved) {
  std::vector<DiffusionCurve> curves = image.curves;
  for (int i : waved) {
    if (closedContour(curves[i])) curves[i] = withoutTeeth(curves[i]);
  }
  return curves;
}

// `curve` as curvesAsWaved gives it. Null when the curve stays unchanged (the report says why).
std::unique_ptr<WavedContour> prepare(const DiffusionCurve& curve, int index,
                                      const Context& context, CurveWaveReport& report) {
  report.curve = index;
  report.requested_amplitude_mm = context.spec.amplitude_mm;
  if (!closedContour(curve)) {
    report.skipped = "not a closed curve";
    return nullptr;
  }
  std::unique_ptr<WavedContour> contour(new WavedContour{
      bspline::toSplineDiffusionCurve(curve), nullptr, nullptr, nullptr, {}, {}, report});
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

// The contours as polylines for the polygon check, with the spline parameter (= original arc
// length) of each point of a waved one. Two samplings: the pieces the renderer draws
// (dci/flattening.hpp), where a crossing would show as a smudge of one side's colour in the
// other, and 16 points per span, finer on short, nearly straight spans, where two parts of a
// contour can overlap by a sliver or loop over a few hundredths of a pixel. Only the contours a
// repair round rebuilt are sampled again.
class ContourPolygons {
 public:
  enum class Sampling { kAsDrawn, kDense };

  /// An unwaved curve's polygon in `sampling`.
  static Polyline polygonOf(const DiffusionCurve& curve, Sampling sampling) {
    return sampling == Sampling::kAsDrawn ? flattenCurve(curve) : sampleCurve(curve, 16);
  }

  ContourPolygons(const DiffusionCurveImage& image,
                  const std::map<int, std::unique_ptr<WavedContour>>& waved, Sampling sampling)
      : image_(image),
        waved_(waved),
        sampling_(sampling),
        lines_(image.curves.size()),
        parameters_(image.curves.size()),
        stale_(image.curves.size(), 1) {}

  const std::vector<Polyline>& lines() {
    for (std::size_t i = 0; i < lines_.size(); ++i) {
      if (!stale_[i]) continue;
      stale_[i] = 0;
      const auto found = waved_.find(static_cast<int>(i));
      if (found == waved_.end()) {
        lines_[i] = polygonOf(image_.curves[i], sampling_);
      } else {
        const bspline::BSplineCurve& curve = found->second->wave->curve;
        lines_[i] = sampling_ == Sampling::kAsDrawn ? curve.flattenSpans(parameters_[i])
                                                    : curve.sampleSpans(16, parameters_[i]);
      }
    }
    return lines_;
  }
  /// The spline parameter at the start of `segment` of waved contour `line`.
  double parameterAt(int line, int segment) const { return parameters_[line][segment]; }
  void rebuilt(int line) { stale_[line] = 1; }

 private:
  const DiffusionCurveImage& image_;
  const std::map<int, std::unique_ptr<WavedContour>>& waved_;
  Sampling sampling_;
  std::vector<Polyline> lines_;
  std::vector<std::vector<double>> parameters_;
  std::vector<char> stale_;
};

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
  std::vector<std::size_t> near;
  for (;;) {
    peaksNear(layout, u, window, near);
    const bool reducible =
        std::any_of(near.begin(), near.end(), [&](std::size_t i) { return applied(i) > 0.0; });
    if (reducible || window >= 0.5 * layout.length) break;
    window += half_period;
  }
  for (const std::size_t i : near) {
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
    for (const auto sampling :
         {ContourPolygons::Sampling::kAsDrawn, ContourPolygons::Sampling::kDense}) {
      std::vector<Polyline> lines;
      for (const DiffusionCurve& curve : image.curves) {
        lines.push_back(ContourPolygons::polygonOf(curve, sampling));
      }
      for (const Crossing& crossing : finder.find(lines)) {
        points_[{crossing.a.line, crossing.b.line}].push_back(crossingPoint(lines, crossing));
      }
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

// One round of the polygon check on `polygons`: caps the waves around every crossing that the
// original contours do not have. Returns the number of such crossings and, per image curve, the
// crossings on it (`left`) and whether its wave was capped (`changed`).
struct RoundOutcome {
  int crossings = 0;
  std::map<int, int> left;
  std::map<int, bool> changed;
};

RoundOutcome capAtCrossings(ContourPolygons& polygons, const DiffusionCurveImage& image,
                            std::map<int, std::unique_ptr<WavedContour>>& waved, int round,
                            CrossingFinder& finder, std::optional<InheritedCrossings>& inherited) {
  RoundOutcome outcome;
  const std::vector<Polyline>& lines = polygons.lines();
  const int last_round = kMaxRepairRounds + kMaxFlatteningRounds;
  for (const Crossing& crossing : finder.find(lines)) {
    if (!inherited) inherited.emplace(image, finder);  // at the first crossing: most have none
    if (inherited->contains(lines, crossing)) continue;
    ++outcome.crossings;
    for (const SegmentRef& side : {crossing.a, crossing.b}) {
      ++outcome.left[side.line];
      const auto found = waved.find(side.line);
      if (found == waved.end() || round == last_round) continue;
      capAround(*found->second, polygons.parameterAt(side.line, side.segment),
                round + 1 >= kMaxRepairRounds);
      outcome.changed[side.line] = true;
    }
  }
  return outcome;
}

// The polygon check after the skeleton guard; returns the crossings left per image curve
// (those the original contours have themselves neither repaired nor counted). A round searches
// the contours as drawn and, where they do not cross, 16 points per span: that search, as
// costly as the first, runs about once per glyph.
std::map<int, int> repairCrossings(const DiffusionCurveImage& image,
                                   std::map<int, std::unique_ptr<WavedContour>>& waved,
                                   const Context& context) {
  std::optional<InheritedCrossings> inherited;
  CrossingFinder finder;
  ContourPolygons drawn(image, waved, ContourPolygons::Sampling::kAsDrawn);
  std::optional<ContourPolygons> dense;
  RoundOutcome outcome;
  for (int round = 0; round <= kMaxRepairRounds + kMaxFlatteningRounds; ++round) {
    outcome = capAtCrossings(drawn, image, waved, round, finder, inherited);
    if (outcome.crossings == 0) {
      if (!dense) dense.emplace(image, waved, ContourPolygons::Sampling::kDense);
      outcome = capAtCrossings(*dense, image, waved, round, finder, inherited);
    }
    if (outcome.changed.empty()) break;
    for (const auto& entry : outcome.changed) {
      build(*waved[entry.first], context);
      drawn.rebuilt(entry.first);
      if (dense) dense->rebuilt(entry.first);
    }
  }
  return outcome.left;
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

std::vector<Polyline> skeletonGuardPolylines(const std::vector<DiffusionCurve>& curves) {
  Flattening flattening;
  flattening.tolerance = 0.005;
  flattening.max_piece_length = 8.0;
  std::vector<Polyline> lines;
  for (const DiffusionCurve& curve : curves) {
    lines.push_back(flattenCurve(curve, nullptr, flattening));
  }
  return lines;
}

std::vector<CurveWaveReport> applyWaves(DiffusionCurveImage& image,
                                        const std::vector<int>& curves_in, const WaveSpec& spec,
                                        double glyph_size_mm, const WaveOptions& options) {
  checkArguments(image, curves_in, spec, glyph_size_mm);
  std::vector<int> curves = curves_in;
  std::sort(curves.begin(), curves.end());
  curves.erase(std::unique(curves.begin(), curves.end()), curves.end());
  const double px_per_mm = image.width / glyph_size_mm;
  const std::vector<DiffusionCurve> as_waved = curvesAsWaved(image, curves);
  std::unique_ptr<NearestCurvePoint> field;
  std::unique_ptr<SkeletonGuard> guard;
  if (options.prevent_self_intersection && !image.curves.empty()) {
    field = std::make_unique<NearestCurvePoint>(skeletonGuardPolylines(as_waved), image.width,
                                                std::max(image.height, 1), options.field_grid_scale,
                                                options.nearest_point_method);
    guard = std::make_unique<SkeletonGuard>(*field, options.skeleton_offset_mm * px_per_mm);
  }
  const Context context{spec, px_per_mm, guard.get()};
  std::vector<CurveWaveReport> reports(curves.size());
  std::map<int, std::unique_ptr<WavedContour>> waved;
  for (std::size_t k = 0; k < curves.size(); ++k) {
    std::unique_ptr<WavedContour> contour =
        prepare(as_waved[curves[k]], curves[k], context, reports[k]);
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
