#include "vicc_glyphs/pacemod/contour_waves.hpp"

#include <algorithm>
#include <stdexcept>

#include "vicc_glyphs/bspline/fitting.hpp"
#include "vicc_glyphs/bspline/fowler_bartels.hpp"
#include "vicc_glyphs/bspline/frenet_frame.hpp"
#include "vicc_glyphs/bspline/knot_insertion.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

using bspline::BSplineCurve;

constexpr int kSamplesPerSpan = 8;

// Outward unit normal of the fit; at the closing point the mean of both ends' normals, so that
// the first and the last knot point move to the same place and the contour stays closed.
Point2 outwardNormal(const BSplineCurve& fit, double arc_length, double area) {
  const double end = fit.domainEnd();
  if (arc_length <= 0.0 || arc_length >= end) {
    const Point2 mean =
        bspline::inwardNormalAt(fit, 0.0, area) + bspline::inwardNormalAt(fit, end, area);
    if (mean.norm() > 1e-9) return -mean.normalized();
  }
  return -bspline::inwardNormalAt(fit, arc_length, area);
}

// Equal first derivatives at both ends of a closed contour: the mean of the fit's.
std::vector<bspline::CurveConstraint> seamConstraints(const BSplineCurve& fit) {
  const Point2 mean =
      0.5 * (fit.derivativeAt(fit.domainBegin()) + fit.derivativeAt(fit.domainEnd()));
  return {{fit.domainBegin(), mean, 1}, {fit.domainEnd(), mean, 1}};
}

void straighten(std::vector<Point2>& points, int first) {
  const Point2 from = points[first], to = points[first + 3];
  points[first + 1] = from + (to - from) / 3.0;
  points[first + 2] = from + 2.0 * (to - from) / 3.0;
}

std::vector<Point2> targetsOf(const ContourWave& wave) {
  std::vector<Point2> targets;
  for (std::size_t i = 0; i < wave.knot_points.size(); ++i) {
    targets.push_back(wave.knot_points[i] + wave.guarded[i].amplitude * wave.directions[i]);
  }
  return targets;
}

// Translated knot points by Fowler-Bartels on `fit` (sine and rectangle).
BSplineCurve translateKnotPoints(const BSplineCurve& fit, const ContourWave& wave) {
  std::vector<bspline::CurveConstraint> constraints = seamConstraints(fit);
  const std::vector<Point2> targets = targetsOf(wave);
  for (std::size_t i = 0; i < targets.size(); ++i) {
    constraints.push_back({wave.layout.peaks[i].arc_length, targets[i], 0});
  }
  return bspline::fowlerBartelsModify(fit, constraints);
}

// Index of the layout peak nearest to `arc_length`.
std::size_t nearestPeak(const WaveLayout& layout, double arc_length) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < layout.peaks.size(); ++i) {
    if (std::abs(layout.peaks[i].arc_length - arc_length) <
        std::abs(layout.peaks[best].arc_length - arc_length)) {
      best = i;
    }
  }
  return best;
}

// Rectangle: corner knots raised to multiplicity 3 (Boehm), every de Boor point first moved with
// its nearest knot point along the normal at its Greville abscissa, so that the plateaus follow
// the offset contour, then Fowler-Bartels meets the knot points exactly and the flanks are
// made straight.
BSplineCurve rectangleWave(const BSplineCurve& fit, double area, const ContourWave& wave) {
  BSplineCurve raised = fit;
  for (const WaveKnot& knot : wave.layout.interior_knots) {
    if (knot.multiplicity > 1) {
      raised = bspline::insertKnot(raised, knot.arc_length, knot.multiplicity - 1);
    }
  }
  std::vector<Point2> points = raised.controlPoints();
  const std::vector<double>& knots = raised.knots();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double greville = (knots[i + 1] + knots[i + 2] + knots[i + 3]) / 3.0;
    const std::size_t peak = nearestPeak(wave.layout, greville);
    points[i] += wave.guarded[peak].amplitude * wave.layout.peaks[peak].sign *
                 outwardNormal(fit, greville, area);
  }
  raised.setControlPoints(points);
  BSplineCurve moved = translateKnotPoints(raised, wave);
  points = moved.controlPoints();
  for (const ArcInterval& span : wave.layout.straight_spans) {
    straighten(points, cornerControlIndex(moved, span.begin));
  }
  moved.setControlPoints(std::move(points));
  return moved;
}

// Triangle and sawtooth: straight strips between the translated corners.
BSplineCurve stripWave(const ContourWave& wave) {
  const std::vector<Point2> corners = targetsOf(wave);
  std::vector<Point2> points{corners.front()};
  for (std::size_t i = 1; i < corners.size(); ++i) {
    points.insert(points.end(), 3, corners[i]);
    straighten(points, static_cast<int>(points.size()) - 4);
  }
  return BSplineCurve(3, knotVector(wave.layout), std::move(points));
}

}  // namespace

BSplineCurve fitOnArcLength(const BSplineCurve& original, const bspline::ArcLengthTable& table,
                            const std::vector<double>& knots) {
  std::vector<double> lengths;
  for (std::size_t i = 3; i + 4 < knots.size(); ++i) {
    if (knots[i + 1] <= knots[i]) continue;
    for (int k = 0; k < kSamplesPerSpan; ++k) {
      lengths.push_back(knots[i] + (knots[i + 1] - knots[i]) * k / kSamplesPerSpan);
    }
  }
  lengths.push_back(knots.back());
  std::vector<Point2> points;
  for (double l : lengths) points.push_back(original.pointAt(table.parameterAt(l)));
  return bspline::leastSquaresFit(3, knots, points, lengths);
}

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

ContourWave modifyContour(const BSplineCurve& original, const bspline::ArcLengthTable& table,
                          Waveform waveform, int wave_count, double amplitude,
                          const SkeletonGuard* guard) {
  if (!original.isClosed(1e-6)) throw std::invalid_argument("modifyContour: contour is not closed");
  ContourWave wave{original, waveLayout(waveform, wave_count, table.totalLength()), {}, {}, {}};
  const BSplineCurve fit = fitOnArcLength(original, table, knotVector(wave.layout, true));
  const double area = bspline::signedArea(fit);
  for (const WavePeak& peak : wave.layout.peaks) {
    const bool closing = peak.arc_length >= wave.layout.length;
    // The closing point repeats the first: same point, direction and amplitude.
    if (closing && !wave.knot_points.empty()) {
      wave.knot_points.push_back(wave.knot_points.front());
      wave.directions.push_back(wave.directions.front());
      wave.guarded.push_back(wave.guarded.front());
      continue;
    }
    const Point2 knot = original.pointAt(table.parameterAt(peak.arc_length));
    const Point2 direction = peak.sign * outwardNormal(fit, peak.arc_length, area);
    wave.knot_points.push_back(knot);
    wave.directions.push_back(direction);
    wave.guarded.push_back(guard ? guard->limit(knot, direction, amplitude)
                                 : GuardResult{std::max(amplitude, 0.0), false, 0});
  }
  switch (waveform) {
    case Waveform::Sine:
      wave.curve = translateKnotPoints(fit, wave);
      break;
    case Waveform::Rectangle:
      wave.curve = rectangleWave(fit, area, wave);
      break;
    case Waveform::Triangle:
    case Waveform::Sawtooth:
      wave.curve = stripWave(wave);
      break;
  }
  return wave;
}

}  // namespace pacemod
}  // namespace vicc_glyphs
