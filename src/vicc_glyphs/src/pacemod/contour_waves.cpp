#include "vicc_glyphs/pacemod/contour_waves.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "bend_refit.hpp"
#include "offset_fit.hpp"
#include "vicc_glyphs/bspline/frenet_frame.hpp"
#include "vicc_glyphs/pacemod/original_splice.hpp"
#include "vicc_glyphs/pacemod/polyline.hpp"
#include "vicc_glyphs/pacemod/sparse_fowler_bartels.hpp"
#include "wave_strips.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace detail {

struct FrameSamples {
  /// Per layout peak (at a smooth closing point the mean of both ends' normals).
  std::vector<ContourSample> peaks;
  /// Per straight span of the layout (the rectangle's flanks): stripSamples.
  std::vector<std::vector<ContourSample>> flanks;
};

// Where knot point `i` goes: from `base` along the unit `direction` (sign included) by a
// translation that puts it `growth` times as far from the contour, met at `parameter`.
struct Placement {
  double parameter = 0.0;
  Point2 base = Point2::Zero();
  Point2 direction = Point2::Zero();
  double growth = 1.0;
  int corner = -1;
  /// At a corner's offset point without moving onto the corner (strips): valid only for an
  /// amplitude that puts the knot point's own offset point past the corner's bisector.
  bool at_miter = false;
};

// A knot point's place and the guard's verdict there (see placeOnCornerOrOwn).
struct GuardedPlacement {
  Placement placement;
  GuardResult allowed;    ///< the guard's amplitude at `placement` (caps not applied)
  bool cornered = false;  ///< `allowed` limited by bisectorCap
};

}  // namespace detail

struct GuardVerdicts::Store {
  const ContourFrame* frame = nullptr;
  const SkeletonGuard* guard = nullptr;
  double amplitude = std::numeric_limits<double>::quiet_NaN();
  std::vector<char> known;
  std::vector<double> cap;  ///< the cap each verdict was made under (infinity: none)
  std::vector<detail::GuardedPlacement> verdict;
};

GuardVerdicts::GuardVerdicts() : store_(std::make_unique<Store>()) {}
GuardVerdicts::~GuardVerdicts() = default;
GuardVerdicts::GuardVerdicts(GuardVerdicts&&) noexcept = default;
GuardVerdicts& GuardVerdicts::operator=(GuardVerdicts&&) noexcept = default;

namespace {

using bspline::BSplineCurve;
using detail::ContourSample;
using detail::GuardedPlacement;
using detail::OffsetFrame;
using detail::Placement;
using detail::StripPiece;

// Arc lengths closer than this (px) are the same place: an icon corner on a wave's knot.
constexpr double kSameArcLength = 1e-3;
// A knot point moves onto an icon corner at most this fraction of the way to its neighbours.
constexpr double kMaxMoveToCorner = 0.5;
// Knots added where the smooth waveforms' fit leaves the contour by more than this (px).
constexpr double kFitTolerance = 0.03;
constexpr int kMaxRefinements = 4;
constexpr int kRefinementProbes = 4;     // places checked per knot span
constexpr double kMinRefinedSpan = 0.5;  // px: spans shorter than twice this stay
// A strip is split at its middle where one cubic leaves the contour's offset path by more than
// this (px), at most kMaxStripSplits times, into pieces no shorter than kMinStripPiece (px).
constexpr double kStripTolerance = 0.05;
constexpr int kMaxStripSplits = 3;
constexpr double kMinStripPiece = 2.0;
// A strip that ends at an icon corner is split where it leaves the offset path by more than this
// fraction of its larger end offset (a deviation that large reads as a lobe of its own).
constexpr double kCornerStripDeviation = 0.5;
// Its half away from the corner, where the path is the contour's plain offset, is held to this
// fraction of the offset when the strip is longer than kLongCornerStrip times its larger end
// offset (a sawtooth's 46 px flank on a bend at 2 waves/10 mm, 1 px amplitude: the whole
// flank's cubic left the far half by 0.45 px, a lobe of 1.33 px for 1.02).
constexpr double kCornerStripFarDeviation = 0.2;
constexpr double kLongCornerStrip = 8.0;
// A knot point limited on an icon corner is reported when it keeps less than this of its
// amplitude.
constexpr double kCornerShortfall = 0.99;
// The rectangle's profile bends at a knot point where its step changes by more than this
// fraction of the amplitude (bend_refit.hpp): the fit overshoots by up to a tenth of the step,
// 2.5 % of the amplitude for smaller ones.
constexpr double kBendStep = 0.25;
// A bend's window is fitted again where the curve leaves the offset path by more than this
// fraction of the amplitude (and kFitTolerance).
constexpr double kBendDeviation = 0.03;

// The knot vector `knots` (clamped cubic over [0, L]) with the contour's corners added as
// triple knots at their arc lengths (an existing knot at the same place is raised), so that
// re-fitting keeps the icon's sharp corners where they are instead of rounding them.
std::vector<double> withContourCorners(std::vector<double> knots,
                                       const std::vector<ContourCorner>& corners) {
  const double end = knots.back();
  for (const ContourCorner& corner : corners) {
    double at = corner.arc_length;
    if (at <= 0.0 || at >= end) continue;
    const auto upper = std::upper_bound(knots.begin(), knots.end(), at);
    if (at - *(upper - 1) < kSameArcLength) at = *(upper - 1);
    if (upper != knots.end() && *upper - at < kSameArcLength) at = *upper;
    if (at <= 0.0 || at >= end) continue;
    const int present = static_cast<int>(std::count(knots.begin(), knots.end(), at));
    knots.insert(std::upper_bound(knots.begin(), knots.end(), at), std::max(0, 3 - present), at);
  }
  return knots;
}

// The knot vector `knots` (withContourCorners' result) with a knot added in the middle of each
// span next to an icon corner (spans shorter than twice kMinRefinedSpan stay). Around a corner
// the offset contour turns through an arc (outside the angle) or runs into the miter (inside
// it) within a few |w| of the corner; one cubic span from the corner to the next wave knot
// could not follow that and its side's offset, and bulged by up to 16 % of the amplitude
// beside the corner (rectangle plateaus at 2-4 waves/10 mm on the MDI bench; 31 -> 15 lobes
// outside 10 %). The rectangle only: on the sine the extra knots moved bulges around rather
// than removing them (MDI 7 -> 5 lobes outside 10 %, but inside the 72-degree corners of a
// test triangle the curve passed the miter by up to 6.6 % of the amplitude instead of 0.5 %).
std::vector<double> withCornerSpansSplit(std::vector<double> knots,
                                         const std::vector<ContourCorner>& corners) {
  const double end = knots.back();
  std::vector<double> added;
  auto split = [&](double a, double b) {
    if (b - a >= 2.0 * kMinRefinedSpan) added.push_back(0.5 * (a + b));
  };
  for (const ContourCorner& corner : corners) {
    const double at = corner.arc_length;
    const double back = at > 0.0 ? at : end;  // the closing corner is at 0 and at L
    const auto after = std::upper_bound(knots.begin(), knots.end(), at + kSameArcLength);
    if (after != knots.end()) split(at, *after);
    const auto before = std::lower_bound(knots.begin(), knots.end(), back - kSameArcLength);
    if (before != knots.begin()) split(*(before - 1), back);
  }
  // A span between two corners is split once.
  std::sort(added.begin(), added.end());
  added.erase(std::unique(added.begin(), added.end()), added.end());
  knots.insert(knots.end(), added.begin(), added.end());
  std::sort(knots.begin(), knots.end());
  return knots;
}

// The knot withContourCorners made for the icon corner at arc length l (it may have raised a
// knot up to kSameArcLength away).
double cornerKnot(const BSplineCurve& curve, double l) {
  const auto at = std::lower_bound(curve.knots().begin(), curve.knots().end(), l - kSameArcLength);
  return at != curve.knots().end() && *at <= l + kSameArcLength ? *at : l;
}

bool closesAtACorner(const ContourFrame& frame) {
  return !frame.corners.empty() && frame.corners.front().arc_length == 0.0;
}

// Equal first derivatives at both ends of a contour that closes smoothly: the mean of the fit's.
std::vector<bspline::CurveConstraint> seamConstraints(const ContourFrame& frame,
                                                      const BSplineCurve& fit) {
  if (closesAtACorner(frame)) return {};
  const Point2 mean =
      0.5 * (fit.derivativeAt(fit.domainBegin()) + fit.derivativeAt(fit.domainEnd()));
  return {{fit.domainBegin(), mean, 1}, {fit.domainEnd(), mean, 1}};
}

bool isStripWaveform(Waveform waveform) {
  return waveform == Waveform::Triangle || waveform == Waveform::Sawtooth;
}

// The icon corner that knot point `i` goes to, or -1: a corner at the same place or, for the
// waveforms whose knot points are free to move (not the rectangle's dense plateau and flank
// points), one inside whose angle the offset of the knot point (by `amplitude`) would fall past
// the bisector. Such a knot point moves onto the corner if that is within kMaxMoveToCorner of
// the way to its neighbours (`moves`); the strips' knot points go to the corner's offset point
// (the miter) even where they cannot move, since their own offset point, past the bisector, is
// nearer the other side than the amplitude. The first and the last knot point stay at the
// closing point.
struct PeakCorner {
  int corner = -1;
  bool moves = false;
  double arc_length = 0.0;  ///< the corner's arc length (L for the closing corner near the end)
};

PeakCorner cornerOfPeak(const ContourFrame& frame, std::size_t i, double amplitude) {
  const std::vector<WavePeak>& peaks = frame.layout.peaks;
  if (i == 0 || i + 1 == peaks.size()) {
    return {closesAtACorner(frame) ? 0 : -1, true, i == 0 ? 0.0 : frame.layout.length};
  }
  const double l = peaks[i].arc_length;
  const double room =
      kMaxMoveToCorner * std::min(l - peaks[i - 1].arc_length, peaks[i + 1].arc_length - l);
  const bool may_move = frame.layout.waveform != Waveform::Rectangle;
  const bool to_miter = isStripWaveform(frame.layout.waveform);
  PeakCorner best;
  double best_distance = 0.0;
  // Beyond the larger of these no corner can take the knot point (see `moves` and `shifts`).
  const double reach = std::max(kSameArcLength, maxSwallowtail(amplitude));
  forEachCornerNear(frame.corners, l, reach, frame.layout.length, [&](int c) {
    const ContourCorner& corner = frame.corners[c];
    double at = corner.arc_length;
    if (at == 0.0 && l > 0.5 * frame.layout.length) at = frame.layout.length;
    const double distance = std::abs(at - l);
    const double swallowtail = corner.swallowtail(peaks[i].sign * amplitude);
    const bool moves =
        distance < kSameArcLength || (may_move && distance < std::min(room, swallowtail));
    // Only a corner within the strips next to the knot point: the knot points keep their
    // order, and its neighbour on the corner (if any) lies outside the angle.
    const bool next_to = at >= peaks[i - 1].arc_length && at <= peaks[i + 1].arc_length;
    // The miter lies swallowtail - distance further along the side than the knot point's own
    // offset point; no further than its neighbours.
    const bool shifts = distance < swallowtail && swallowtail - distance < 2.0 * room;
    if ((moves || (to_miter && next_to && shifts)) &&
        (best.corner < 0 || distance < best_distance)) {
      best = {c, moves, at};
      best_distance = distance;
    }
  });
  return best;
}

Placement placePeak(const ContourFrame& frame, std::size_t i, double amplitude) {
  const WavePeak& peak = frame.layout.peaks[i];
  Placement placement;
  const PeakCorner to = cornerOfPeak(frame, i, amplitude);
  placement.corner = to.corner;
  if (placement.corner >= 0) {
    const ContourCorner& corner = frame.corners[placement.corner];
    placement.parameter = to.moves ? to.arc_length : peak.arc_length;
    placement.at_miter = !to.moves;
    placement.base = corner.point;
    placement.direction = peak.sign * corner.bisector;
    // The strips follow a knot point inside the angle to its miter; the smooth waveforms'
    // offset contour cannot reach it (the neighbours' offsets meet the bisector first), so
    // there the thesis' half-space test decides how far it may go along the bisector.
    placement.growth =
        isStripWaveform(frame.layout.waveform) ? 1.0 / corner.stretch(peak.sign * amplitude) : 1.0;
    return placement;
  }
  const ContourSample& sample = frame.samples->peaks[i];
  placement.parameter = peak.arc_length;
  placement.base = sample.point;
  placement.direction = peak.sign * sample.normal;
  return placement;
}

GuardResult guardedAmplitude(const Placement& placement, double amplitude,
                             const SkeletonGuard* guard) {
  return guard ? guard->limit(placement.base, placement.direction, amplitude, placement.growth)
               : GuardResult{std::max(amplitude, 0.0), false, 0};
}

// placePeak for the amplitude the knot point can have, with the skeleton guard's verdict on
// that place: a strip knot point goes to a corner's miter only while its own offset point, by
// that amplitude, would fall past the bisector. With less (a repair round's cap, the skeleton
// guard) its own offset point is the offset contour, and the miter, further along the side,
// would make the strips next to it run back.
GuardedPlacement placeOnCornerOrOwn(const ContourFrame& frame, std::size_t i, double amplitude,
                                    const SkeletonGuard* guard, const std::vector<double>& caps) {
  const Placement placement = placePeak(frame, i, amplitude);
  const GuardResult allowed = guardedAmplitude(placement, amplitude, guard);
  if (!placement.at_miter) return {placement, allowed};
  double kept = allowed.amplitude;
  if (i < caps.size()) kept = std::min(kept, std::max(caps[i], 0.0));
  if (kept >= amplitude) return {placement, allowed};
  const Placement own = placePeak(frame, i, kept);
  if (!own.at_miter && own.corner >= 0) return {placement, allowed};
  return {own, guardedAmplitude(own, amplitude, guard)};
}

// Strips: the amplitude a knot point at its own offset point (no icon corner, no miter) may
// keep near an icon corner inside whose angle its offset `w` falls. Within the swallowtail the
// corner's bisector is the skeleton, so the thesis' half-space test is exact there: a' = the
// offset that reaches the bisector at arc distance |d| from the corner, |d| / tan(turn / 2),
// less epsilon. The guard's grid field misses this by up to its pixel of accuracy, enough at a
// sharp tip (a star's, a lightning bolt's) for the offset point to land past the tip's other
// side. Infinity where no corner limits it.
double bisectorCap(const ContourFrame& frame, double l, double w, double epsilon) {
  const double end = frame.layout.length;
  double cap = std::numeric_limits<double>::infinity();
  forEachCornerNear(frame.corners, l, maxSwallowtail(w), end, [&](int c) {
    const ContourCorner& corner = frame.corners[c];
    const double swallowtail = corner.swallowtail(w);
    if (swallowtail <= 0.0) return;
    const double d = cyclicDistance(l, corner.arc_length, end);  // the closing corner: 0 and L
    if (d >= swallowtail) return;
    cap = std::min(cap, std::max(0.0, corner.bisectorOffsetAt(d) - epsilon));
  });
  return cap;
}

// placeOnCornerOrOwn, and for a strip knot point at its own offset point the exact test at the
// icon corners (bisectorCap).
GuardedPlacement placeGuardedPeak(const ContourFrame& frame, std::size_t i, double amplitude,
                                  const SkeletonGuard* guard, const std::vector<double>& caps) {
  GuardedPlacement result = placeOnCornerOrOwn(frame, i, amplitude, guard, caps);
  if (!guard || !isStripWaveform(frame.layout.waveform) || result.placement.corner >= 0) {
    return result;
  }
  const double w = frame.layout.peaks[i].sign * amplitude;
  const double cap = bisectorCap(frame, result.placement.parameter, w, guard->epsilon());
  if (cap < result.allowed.amplitude) {
    result.allowed.amplitude = cap;
    result.cornered = true;
  }
  return result;
}

// placeGuardedPeak, or the verdict `verdicts` holds for knot point i under the same cap. The
// verdict depends on the cap only through min(guard's amplitude, max(cap, 0)), and the guard
// never allows more than the amplitude: a cap at or above it is no cap.
GuardedPlacement rememberedPeak(const ContourFrame& frame, std::size_t i, double amplitude,
                                const SkeletonGuard* guard, const std::vector<double>& caps,
                                GuardVerdicts* verdicts) {
  if (!verdicts) return placeGuardedPeak(frame, i, amplitude, guard, caps);
  GuardVerdicts::Store& store = verdicts->store();
  const std::size_t count = frame.layout.peaks.size();
  if (store.frame != &frame || store.guard != guard || !(store.amplitude == amplitude) ||
      store.known.size() != count) {
    store = GuardVerdicts::Store{
        &frame, guard, amplitude, std::vector<char>(count, 0), std::vector<double>(count), {}};
    store.verdict.resize(count);
  }
  const double cap = i < caps.size() && caps[i] < amplitude
                         ? std::max(caps[i], 0.0)
                         : std::numeric_limits<double>::infinity();
  if (!store.known[i] || store.cap[i] != cap) {
    store.verdict[i] = placeGuardedPeak(frame, i, amplitude, guard, caps);
    store.cap[i] = cap;
    store.known[i] = 1;
  }
  return store.verdict[i];
}

// The original's points and normals that placePeak and smoothWave take, for every amplitude.
std::shared_ptr<const detail::FrameSamples> frameSamples(const ContourFrame& frame,
                                                         const OffsetFrame& offsets) {
  auto samples = std::make_shared<detail::FrameSamples>();
  const double end = frame.layout.length;
  for (const WavePeak& peak : frame.layout.peaks) {
    const double l = peak.arc_length;
    ContourSample sample = offsets.sample(l);
    if (l <= 0.0 || l >= end) {  // a smooth closing point: both ends move the same way
      const Point2 mean = offsets.normal(0.0) + offsets.normal(end);
      if (mean.norm() > 1e-9) sample.normal = mean.normalized();
    }
    samples->peaks.push_back(sample);
  }
  for (const ArcInterval& span : frame.layout.straight_spans) {
    samples->flanks.push_back(detail::stripSamples(offsets, span.begin, span.end));
  }
  return samples;
}

double appliedOffset(const ContourWave& wave, std::size_t i) {
  return wave.layout.peaks[i].sign * wave.guarded[i].amplitude;
}

Point2 targetOf(const ContourWave& wave, std::size_t i) {
  return wave.knot_points[i] + wave.translations[i] * wave.directions[i];
}

// The wave's signed offset at arc length l between its knot points: the sine's half cosine,
// linear for the others.
double waveOffsetAt(const ContourWave& wave, double l, std::size_t next) {
  const std::vector<double>& at = wave.parameters;
  const double span = at[next] - at[next - 1];
  double t = span > 0.0 ? std::clamp((l - at[next - 1]) / span, 0.0, 1.0) : 0.0;
  if (wave.layout.waveform == Waveform::Sine) t = 0.5 - 0.5 * std::cos(M_PI * t);
  return (1.0 - t) * appliedOffset(wave, next - 1) + t * appliedOffset(wave, next);
}

// The knot point after arc length l: the first parameter above l, clamped to [1, count - 1].
std::size_t knotPointAfter(const std::vector<double>& at, double l) {
  return std::clamp<std::size_t>(std::upper_bound(at.begin(), at.end(), l) - at.begin(), 1,
                                 at.size() - 1);
}

double waveOffsetAt(const ContourWave& wave, double l) {
  return waveOffsetAt(wave, l, knotPointAfter(wave.parameters, l));
}

// waveOffsetAt as an OffsetFit::Offset. The fit asks at its samples in increasing order, one
// or a few per knot span: the span of the last call, or the one after it, is tried before a
// search (with parameters that do not decrease, the same span the search would find).
class WaveProfile {
 public:
  explicit WaveProfile(const ContourWave& wave)
      : wave_(&wave), sorted_(std::is_sorted(wave.parameters.begin(), wave.parameters.end())) {}

  double operator()(double l) {
    const std::vector<double>& at = wave_->parameters;
    if (!(sorted_ && (holds(next_, l) || holds(++next_, l)))) next_ = knotPointAfter(at, l);
    return waveOffsetAt(*wave_, l, next_);
  }

 private:
  // Whether knotPointAfter(l) is `next`: at[next - 1] <= l < at[next], but without the bound
  // that the clamping removes at either end.
  bool holds(std::size_t next, double l) const {
    const std::vector<double>& at = wave_->parameters;
    return next < at.size() && (next == 1 || at[next - 1] <= l) &&
           (next + 1 == at.size() || l < at[next]);
  }

  const ContourWave* wave_;
  bool sorted_;
  std::size_t next_ = 1;
};

bool occupied(const ContourWave& wave, std::size_t corner) {
  return std::find(wave.on_corner.begin(), wave.on_corner.end(), static_cast<int>(corner)) !=
         wave.on_corner.end();
}

// The positions Fowler-Bartels makes `fit` meet: every translated knot point and every icon
// corner no knot point sits on at its target (sine and rectangle), and the seam's tangent.
std::vector<bspline::CurveConstraint> targetConstraints(const BSplineCurve& fit,
                                                        const ContourFrame& frame,
                                                        const ContourWave& wave,
                                                        const std::vector<Point2>& corner_targets) {
  std::vector<bspline::CurveConstraint> constraints = seamConstraints(frame, fit);
  for (std::size_t i = 0; i < wave.parameters.size(); ++i) {
    if (!wave.swallowed[i]) constraints.push_back({wave.parameters[i], targetOf(wave, i), 0});
  }
  for (std::size_t c = 0; c < frame.corners.size(); ++c) {
    const ContourCorner& corner = frame.corners[c];
    if (occupied(wave, c) || corner.arc_length <= 0.0) continue;
    constraints.push_back({cornerKnot(fit, corner.arc_length), corner_targets[c], 0});
  }
  return constraints;
}

// The rectangle's bends at simple knots (bend_refit.hpp): knot points where the profile's step
// from the one before to the one after changes by more than kBendStep of the amplitude, with
// their neighbours (`amplitude`: the wave's largest); bends at consecutive knot points share a
// window.
std::vector<detail::BendWindow> bendWindows(const BSplineCurve& curve, const ContourWave& wave,
                                            double amplitude) {
  std::vector<detail::BendWindow> windows;
  const std::vector<double>& p = wave.parameters;
  std::size_t last_after = 0;  // the index after the last window's last bend
  for (std::size_t i = 1; i + 1 < p.size(); ++i) {
    if (!(p[i - 1] < p[i] && p[i] < p[i + 1]) || curve.multiplicity(p[i]) >= 3) continue;
    const double step_before = appliedOffset(wave, i) - appliedOffset(wave, i - 1);
    const double step_after = appliedOffset(wave, i + 1) - appliedOffset(wave, i);
    if (std::abs(step_after - step_before) <= kBendStep * amplitude) continue;
    if (!windows.empty() && last_after == i) {
      windows.back().knot_points.push_back(p[i + 1]);  // the bend before was at i - 1
    } else {
      windows.push_back({{p[i - 1], p[i], p[i + 1]}});
    }
    last_after = i + 1;
  }
  return windows;
}

// Where knot point i lies against the inner icon corners around it (corners are sorted by arc
// length; only the two around it can hold it), with `meeting` the corners' meeting distances
// (OffsetFit::CornerPassage: the stretch of each side whose offset falls past the bisector):
// - swallowed: within the stretch of a side whose offset falls past the corner's bisector;
// - spread: past that stretch but within the one the offset fit spreads what is left of the
//   side's offset over (OffsetFit::spreadDistance). There the fit takes the offset contour from
//   nearer the corner, while a constraint held the curve at the knot point's own offset point:
//   the curve bulged between them (the pine tree's concave branch corners, 2/10 mm, 0.4 mm:
//   4.55 px for 4.10; rectangle plateaus over corners likewise). Such a knot point gets no
//   constraint either: the spread reaches its amplitude a little nearer the corner.
struct InnerCorner {
  int corner = -1;
  bool swallowed = false;
};

InnerCorner innerCornerOf(const ContourFrame& frame, const ContourWave& wave, std::size_t i,
                          const std::vector<std::pair<double, double>>& meeting) {
  InnerCorner spread;
  if (frame.corners.empty()) return spread;
  const double end = wave.layout.length, l = wave.parameters[i];
  const auto next = std::upper_bound(
      frame.corners.begin(), frame.corners.end(), l,
      [](double value, const ContourCorner& corner) { return value < corner.arc_length; });
  const std::size_t after = (next - frame.corners.begin()) % frame.corners.size();
  const std::size_t before = (after + frame.corners.size() - 1) % frame.corners.size();
  for (std::size_t c : {before, after}) {
    const ContourCorner& corner = frame.corners[c];
    if (!corner.inside(appliedOffset(wave, i))) continue;
    const double d = cyclicOffset(corner.arc_length, l, end);  // the closing corner: 0 and L
    const int side = d < 0.0 ? -1 : 1;
    const double met = side < 0 ? meeting[c].first : meeting[c].second;
    if (std::abs(d) < met) return {static_cast<int>(c), true};
    if (spread.corner < 0 && met > 0.0 &&
        std::abs(d) < frame.offset_fit->spreadDistance(static_cast<int>(c), side, met)) {
      spread.corner = static_cast<int>(c);
    }
  }
  return spread;
}

// Sine and rectangle: inside an icon corner's angle the offset contour of the sides (each by
// its own offset) ends where they meet the bisector. A knot point on the corner goes only that
// far along the bisector; one whose offset would fall past the bisector is left to the offset
// fit (no constraint of its own). Either gets the distance of the meeting point; where that is
// less than its amplitude it is reported ("corner"). One that lies past the meeting point but
// within the stretch the fit spreads (innerCornerOf) is left to the fit too, with its
// amplitude. Twice, as the meeting point moves with the knot points' own amplitudes.
void limitOnCorners(const ContourFrame& frame, ContourWave& wave) {
  const detail::OffsetFit::Offset offset = WaveProfile(wave);
  for (int pass = 0; pass < 2; ++pass) {
    const detail::OffsetFit::CornerPassage passage = frame.offset_fit->cornerPassage(offset);
    const std::vector<Point2>& targets = passage.targets;
    for (std::size_t i = 0; i + 1 < wave.parameters.size(); ++i) {
      int c = wave.on_corner[i];
      if (c < 0) {
        const InnerCorner inner = innerCornerOf(frame, wave, i, passage.meeting);
        if (inner.corner < 0) continue;
        wave.swallowed[i] = true;        // no constraint
        if (!inner.swallowed) continue;  // spread: its amplitude stays
        c = inner.corner;
      } else if (!frame.corners[c].inside(appliedOffset(wave, i))) {
        continue;
      }
      const ContourCorner& corner = frame.corners[c];
      const double along = std::max(
          0.0, wave.layout.peaks[i].sign * (targets[c] - corner.point).dot(corner.bisector));
      const double distance = along * corner.half_turn_cosine;
      if (wave.swallowed[i]) {
        wave.translations[i] = 0.0;  // no constraint: the fit's offset contour decides
      } else if (distance < wave.guarded[i].amplitude) {
        wave.translations[i] = along;
      }
      if (distance < kCornerShortfall * wave.guarded[i].amplitude) {
        wave.guarded[i].amplitude = distance;
        wave.cornered[i] = !wave.capped[i] && !wave.guarded[i].reduced;
      }
    }
    // The closing knot point repeats the first.
    wave.guarded.back() = wave.guarded.front();
    wave.translations.back() = wave.translations.front();
    wave.cornered.back() = wave.cornered.front();
    wave.swallowed.back() = wave.swallowed.front();
  }
}

// Index of the layout peak at arc length `l` (a flank's end).
std::size_t peakAt(const WaveLayout& layout, double l) {
  const auto at =
      std::lower_bound(layout.peaks.begin(), layout.peaks.end(), l,
                       [](const WavePeak& peak, double value) { return peak.arc_length < value; });
  return std::min<std::size_t>(at - layout.peaks.begin(), layout.peaks.size() - 1);
}

// Sine and rectangle: the offset fit of the wave's profile, then Fowler-Bartels for the knot
// points and the icon's corners; where the rectangle's profile bends beside a reduced knot
// point the fit is refined (bend_refit.hpp); its flanks become strips.
BSplineCurve smoothWave(const ContourFrame& frame, const OffsetFrame& offsets,
                        const ContourWave& wave) {
  const detail::OffsetFit::Offset offset = WaveProfile(wave);
  const detail::OffsetFit::CornerPassage passage = frame.offset_fit->cornerPassage(offset);
  const BSplineCurve fit = frame.offset_fit->fit(offset, passage);
  const std::vector<bspline::CurveConstraint> pinned =
      targetConstraints(fit, frame, wave, passage.targets);
  BSplineCurve curve = sparseFowlerBartels(fit, pinned);
  if (wave.layout.waveform == Waveform::Rectangle) {
    std::vector<double> keep_out;
    for (const ContourCorner& corner : frame.corners) keep_out.push_back(corner.arc_length);
    const auto path = [&](double l) { return offsets.offsetPoint(l, waveOffsetAt(wave, l)); };
    double amplitude = 0.0;
    for (const GuardResult& guarded : wave.guarded) {
      amplitude = std::max(amplitude, guarded.amplitude);
    }
    curve = detail::refitBends(curve, bendWindows(curve, wave, amplitude), pinned, keep_out, path,
                               std::max(kFitTolerance, kBendDeviation * amplitude));
  }
  if (wave.layout.straight_spans.empty()) return curve;
  std::vector<Point2> points = curve.controlPoints();
  for (std::size_t k = 0; k < wave.layout.straight_spans.size(); ++k) {
    const ArcInterval& span = wave.layout.straight_spans[k];
    // An icon corner inside the flank splits it; the fit already follows the contour there.
    const int first = cornerControlIndex(curve, span.begin);
    if (cornerControlIndex(curve, span.end) != first + 3) continue;
    detail::fitStrip(points, first,
                     {span.begin, span.end, appliedOffset(wave, peakAt(wave.layout, span.begin)),
                      appliedOffset(wave, peakAt(wave.layout, span.end))},
                     frame.samples->flanks[k]);
  }
  curve.setControlPoints(std::move(points));
  return curve;
}

// A C0 place of a strip wave: a translated knot point, or an icon corner inside a strip (at its
// offset point), or a place where a long strip on a bend is split.
struct StripBreak {
  double arc_length;
  double offset;
  Point2 point;
  const ContourCorner* corner;
  double corner_arc = 0.0;  ///< the corner's arc length nearest to arc_length (StripPiece)
};

// The break of knot point or corner `corner` at arc length l; the corner's arc length is taken
// as the one (of at + k L) nearest to l, so that the closing corner is at L for the strips
// before it.
StripBreak stripBreak(double l, double w, const Point2& point, const ContourCorner* corner,
                      double length) {
  if (!corner) return {l, w, point, nullptr, l};
  const double at = corner->arc_length;
  return {l, w, point, corner, at + length * std::round((l - at) / length)};
}

// Whether the strip from `a` to `b`, fitted as one cubic with `deviation`, stays whole (see
// appendStrip).
bool stripFits(const StripBreak& a, const StripBreak& b, const detail::StripDeviation& deviation) {
  if (!a.corner && !b.corner) return deviation.largest <= kStripTolerance;
  const double offset = std::max(std::abs(a.offset), std::abs(b.offset));
  if (deviation.largest > std::max(kStripTolerance, kCornerStripDeviation * offset)) return false;
  return b.arc_length - a.arc_length <= kLongCornerStrip * offset ||
         deviation.away_from_corner <= std::max(kStripTolerance, kCornerStripFarDeviation * offset);
}

// Fits the strip from `a` to `b` as one cubic, appended to `points` (its inner de Boor points
// and b's), or, where that cubic leaves the contour's offset path by more than
// kStripTolerance (a long strip on a bend: a sawtooth's flank at 2 waves/10 mm is 46 px long),
// as two strips split at the middle (the offset interpolated there), recursively. A strip that
// ends at an icon corner is split only where it leaves the path by more than
// kCornerStripDeviation of its offset: split at kStripTolerance, more knot points were reduced
// by the polygon check than lobes gained (bench, sessions 20 and 22); whole, a strip around an
// asterisk arm's round end (Bootstrap cloud-snow-fill) cut it by 1.8 px at a 1 px amplitude, a
// lobe pair too many. A long one is also split where its half away from the corner leaves the
// path by more than kCornerStripFarDeviation of its offset (a tighter rule for every corner
// strip, tried in session 25, reduced more knot points; this one changes only such flanks).
void appendStrip(const OffsetFrame& offsets, const StripBreak& a, const StripBreak& b, int depth,
                 std::vector<double>& knots, std::vector<Point2>& points) {
  const std::size_t first = points.size() - 1;
  points.insert(points.end(), 3, b.point);
  const detail::StripDeviation deviation =
      detail::fitStrip(points, static_cast<int>(first),
                       {a.arc_length, b.arc_length, a.offset, b.offset, a.corner, b.corner,
                        a.corner_arc, b.corner_arc},
                       offsets);
  if (stripFits(a, b, deviation) || depth == kMaxStripSplits ||
      b.arc_length - a.arc_length < 2.0 * kMinStripPiece) {
    return;
  }
  const double middle = 0.5 * (a.arc_length + b.arc_length);
  const double w = 0.5 * (a.offset + b.offset);
  const StripBreak split{middle, w, offsets.offsetPoint(middle, w), nullptr, middle};
  points.resize(first + 1);
  appendStrip(offsets, a, split, depth + 1, knots, points);
  knots.insert(knots.end(), 3, middle);
  appendStrip(offsets, split, b, depth + 1, knots, points);
}

// Triangle and sawtooth: straight strips between the translated corners. An icon corner inside
// a strip splits it at its offset point (the strip's offset interpolated there), so that the
// wave keeps its distance around the corner instead of cutting it with one cubic.
BSplineCurve stripWave(const ContourFrame& frame, const OffsetFrame& offsets,
                       const ContourWave& wave) {
  std::vector<StripBreak> breaks;
  const std::size_t count = wave.parameters.size();
  for (std::size_t i = 0; i < count; ++i) {
    const ContourCorner* own = wave.on_corner[i] >= 0 ? &frame.corners[wave.on_corner[i]] : nullptr;
    breaks.push_back(stripBreak(wave.parameters[i], appliedOffset(wave, i), targetOf(wave, i), own,
                                wave.layout.length));
    if (i + 1 == count) break;
    const double l0 = wave.parameters[i], l1 = wave.parameters[i + 1];
    // The corners strictly inside the strip: those within half its length of its middle.
    forEachCornerNear(
        frame.corners, 0.5 * (l0 + l1), 0.5 * (l1 - l0), wave.layout.length, [&](int c) {
          const ContourCorner& corner = frame.corners[c];
          if (occupied(wave, c) || corner.arc_length <= l0 + kSameArcLength ||
              corner.arc_length >= l1 - kSameArcLength) {
            return;
          }
          const double w = waveOffsetAt(wave, corner.arc_length);
          breaks.push_back(
              stripBreak(corner.arc_length, w, corner.offsetPoint(w), &corner, wave.layout.length));
        });
  }
  std::vector<double> knots(4, 0.0);
  std::vector<Point2> points{breaks.front().point};
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
    if (k > 0) knots.insert(knots.end(), 3, breaks[k].arc_length);
    appendStrip(offsets, breaks[k], breaks[k + 1], 0, knots, points);
  }
  knots.insert(knots.end(), 4, wave.layout.length);
  return BSplineCurve(3, std::move(knots), std::move(points));
}

// The offset fit on the waveform's knots (and the icon's corners) with knots added in the
// middle of every span where the fit of the contour itself (offset 0) is further than
// kFitTolerance from it, a few times: where the contour has detail finer than a quarter period
// the waveform's knots alone would round it off by up to a few tenths of a pixel, as much as a
// small amplitude (thesis 6.2.3.3: further knots where the B-spline lacks degrees of freedom).
std::shared_ptr<const detail::OffsetFit> adaptedFit(const BSplineCurve& original,
                                                    const bspline::ArcLengthTable& table,
                                                    const ContourFrame& frame) {
  std::vector<double> knots = withContourCorners(knotVector(frame.layout), frame.corners);
  if (frame.layout.waveform == Waveform::Rectangle) {
    knots = withCornerSpansSplit(std::move(knots), frame.corners);
  }
  auto fit = std::make_shared<detail::OffsetFit>(original, table, knots, frame.corners, frame.area);
  const auto zero = [](double) { return 0.0; };
  for (int round = 0; round < kMaxRefinements; ++round) {
    const BSplineCurve curve = fit->fit(zero, fit->cornerPassage(zero));
    std::vector<double> added;
    for (std::size_t i = 3; i + 4 < knots.size(); ++i) {
      const double a = knots[i], b = knots[i + 1];
      if (b - a < 2.0 * kMinRefinedSpan) continue;
      for (int k = 1; k < kRefinementProbes; ++k) {
        const double l = a + (b - a) * k / kRefinementProbes;
        if ((curve.pointAt(l) - original.pointAt(table.parameterAt(l))).norm() > kFitTolerance) {
          added.push_back(0.5 * (a + b));
          break;
        }
      }
    }
    if (added.empty()) break;
    knots.insert(knots.end(), added.begin(), added.end());
    std::sort(knots.begin(), knots.end());
    fit = std::make_shared<detail::OffsetFit>(original, table, knots, frame.corners, frame.area);
  }
  return fit;
}

}  // namespace

int cornerControlIndex(const BSplineCurve& curve, double knot) {
  const std::vector<double>& knots = curve.knots();
  if (knot <= curve.domainBegin()) return 0;
  if (knot >= curve.domainEnd()) return curve.controlPointCount() - 1;
  const auto first = std::lower_bound(knots.begin(), knots.end(), knot);
  if (first == knots.end() || *first != knot || curve.multiplicity(knot) < curve.degree()) {
    throw std::invalid_argument("cornerControlIndex: not a knot of full multiplicity");
  }
  return static_cast<int>(first - knots.begin()) - 1;
}

ContourFrame contourFrame(const BSplineCurve& original, const bspline::ArcLengthTable& table,
                          Waveform waveform, int wave_count) {
  if (!original.isClosed(1e-6)) throw std::invalid_argument("modifyContour: contour is not closed");
  ContourFrame frame{waveLayout(waveform, wave_count, table.totalLength()),
                     bspline::signedArea(original),
                     {},
                     nullptr,
                     nullptr};
  frame.corners = contourCorners(original, table, frame.area);
  frame.samples = frameSamples(frame, OffsetFrame{original, table, frame.area});
  if (waveform == Waveform::Sine || waveform == Waveform::Rectangle) {
    frame.offset_fit = adaptedFit(original, table, frame);
  }
  return frame;
}

ContourWave modifyContour(const ContourFrame& frame, const BSplineCurve& original,
                          const bspline::ArcLengthTable& table, double amplitude,
                          const SkeletonGuard* guard, const std::vector<double>& caps,
                          GuardVerdicts* verdicts) {
  ContourWave wave{original, frame.layout, {}, {}, {}, {}, {}, {}, {}, {}, {}};
  const OffsetFrame offsets{original, table, frame.area};
  const std::size_t count = wave.layout.peaks.size();
  for (std::size_t i = 0; i < count; ++i) {
    // The closing point repeats the first: same point, direction and amplitude.
    if (i + 1 == count && i > 0) {
      wave.parameters.push_back(wave.layout.length);
      wave.on_corner.push_back(wave.on_corner.front());
      wave.knot_points.push_back(wave.knot_points.front());
      wave.directions.push_back(wave.directions.front());
      wave.guarded.push_back(wave.guarded.front());
      wave.capped.push_back(wave.capped.front());
      wave.cornered.push_back(false);
      wave.swallowed.push_back(false);
      wave.translations.push_back(wave.translations.front());
      continue;
    }
    const GuardedPlacement guarded = rememberedPeak(frame, i, amplitude, guard, caps, verdicts);
    const Placement& placement = guarded.placement;
    GuardResult allowed = guarded.allowed;
    const bool capped = i < caps.size() && caps[i] < allowed.amplitude;
    if (capped) allowed.amplitude = std::max(caps[i], 0.0);
    wave.parameters.push_back(placement.parameter);
    wave.on_corner.push_back(placement.corner);
    wave.knot_points.push_back(placement.base);
    wave.directions.push_back(placement.direction);
    wave.guarded.push_back(allowed);
    wave.capped.push_back(capped);
    wave.cornered.push_back(guarded.cornered && !capped);
    wave.swallowed.push_back(false);
    wave.translations.push_back(allowed.amplitude / placement.growth);
  }
  if (frame.offset_fit) limitOnCorners(frame, wave);
  switch (wave.layout.waveform) {
    case Waveform::Sine:
    case Waveform::Rectangle:
      wave.curve = smoothWave(frame, offsets, wave);
      break;
    case Waveform::Triangle:
    case Waveform::Sawtooth:
      wave.curve = stripWave(frame, offsets, wave);
      break;
  }
  // Where the wave is flat the contour stays the original exactly (original_splice.hpp).
  const std::vector<ArcInterval> flat =
      flatRuns(wave.parameters, wave.translations, wave.swallowed);
  if (!flat.empty()) wave.curve = spliceOriginal(wave.curve, original, table, flat);
  return wave;
}

ContourWave modifyContour(const BSplineCurve& original, const bspline::ArcLengthTable& table,
                          Waveform waveform, int wave_count, double amplitude,
                          const SkeletonGuard* guard, const std::vector<double>& caps) {
  return modifyContour(contourFrame(original, table, waveform, wave_count), original, table,
                       amplitude, guard, caps);
}

}  // namespace pacemod
}  // namespace vicc_glyphs
