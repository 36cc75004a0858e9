#include "vicc_glyphs/pacemod/contour_waves.hpp"

#include <Eigen/Cholesky>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <stdexcept>

#include "vicc_glyphs/bspline/fitting.hpp"
#include "vicc_glyphs/bspline/frenet_frame.hpp"
#include "vicc_glyphs/pacemod/polyline.hpp"
#include "vicc_glyphs/pacemod/sparse_fowler_bartels.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

using bspline::BSplineCurve;

constexpr int kSamplesPerSpan = 8;
constexpr int kCornerSteps = 8;
constexpr double kCornerSnap = 0.2;
constexpr double kCornerTolerance = 0.01;
constexpr double kMaxCornerStretch = 2.0;

// The knot vector `knots` (clamped cubic over [0, L]) with the contour's own corners (its C0
// joins) added as triple knots at their arc lengths, so that re-fitting keeps the icon's sharp
// corners instead of rounding them over a knot span. A corner closer than kCornerSnap of a span
// to an existing knot raises that knot to multiplicity 3 instead.
std::vector<double> withContourCorners(std::vector<double> knots, const BSplineCurve& original,
                                       const bspline::ArcLengthTable& table) {
  const double end = knots.back();
  for (double b : original.breakpoints()) {
    if (b <= original.domainBegin() || b >= original.domainEnd() ||
        original.multiplicity(b) < original.degree()) {
      continue;
    }
    const double l = table.lengthAt(b);
    const auto upper = std::upper_bound(knots.begin(), knots.end(), l);
    const double after = upper == knots.end() ? end : *upper;
    const double before = *(upper - 1);
    const double span = after - before;
    double at = l;
    if (l - before < kCornerSnap * span) at = before;
    if (after - l < kCornerSnap * span) at = after;
    if (at <= 0.0 || at >= end) continue;
    const int present = static_cast<int>(std::count(knots.begin(), knots.end(), at));
    knots.insert(std::upper_bound(knots.begin(), knots.end(), at), std::max(0, 3 - present), at);
  }
  return knots;
}

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

// What the strips between corners follow: the original contour offset along the normal by an
// amount that changes linearly from one corner to the next.
struct StripFrame {
  const BSplineCurve& original;
  const bspline::ArcLengthTable& table;
  const BSplineCurve& fit;
  double area;
};

constexpr int kStripSamples = 9;

// Inner control points of the cubic strip points[first .. first+3] between arc lengths l0 and
// l1: least squares (ends fixed) to the offset contour with offsets w0 -> w1. On a straight
// contour this is the straight line with its points at a third and two thirds (Fig. 6.14B);
// on a curved one the strip bends with the contour, so the wave keeps its amplitude.
void fitStrip(std::vector<Point2>& points, int first, double l0, double l1, double w0, double w1,
              const StripFrame& frame) {
  const Point2 p0 = points[first], p3 = points[first + 3];
  Eigen::Matrix2d normal = Eigen::Matrix2d::Zero();
  Eigen::Matrix<double, 2, 2> rhs = Eigen::Matrix<double, 2, 2>::Zero();
  for (int k = 1; k <= kStripSamples; ++k) {
    const double t = static_cast<double>(k) / (kStripSamples + 1);
    const double l = l0 + t * (l1 - l0);
    const Point2 target = frame.original.pointAt(frame.table.parameterAt(l)) +
                          ((1 - t) * w0 + t * w1) * outwardNormal(frame.fit, l, frame.area);
    const double b0 = (1 - t) * (1 - t) * (1 - t), b1 = 3 * t * (1 - t) * (1 - t),
                 b2 = 3 * t * t * (1 - t), b3 = t * t * t;
    const Eigen::Vector2d basis(b1, b2);
    normal += basis * basis.transpose();
    rhs += basis * (target - b0 * p0 - b3 * p3).transpose();
  }
  const Eigen::Matrix2d inner = normal.ldlt().solve(rhs);
  points[first + 1] = inner.row(0).transpose();
  points[first + 2] = inner.row(1).transpose();
}

double signedOffset(const ContourWave& wave, std::size_t peak) {
  return wave.layout.peaks[peak].sign * wave.translations[peak];
}

// Index of the layout peak at exactly `arc_length` (strip ends are knot points).
std::size_t peakAt(const WaveLayout& layout, double arc_length) {
  for (std::size_t i = 0; i < layout.peaks.size(); ++i) {
    if (layout.peaks[i].arc_length == arc_length) return i;
  }
  throw std::invalid_argument("peakAt: strip end is not a knot point");
}

void fitStrips(std::vector<Point2>& points, const BSplineCurve& curve, const ContourWave& wave,
               const StripFrame& frame) {
  for (const ArcInterval& span : wave.layout.straight_spans) {
    // A corner of the icon inside the strip splits it; the fit already follows the contour there.
    const int first = cornerControlIndex(curve, span.begin);
    if (cornerControlIndex(curve, span.end) != first + 3) continue;
    fitStrip(points, first, span.begin, span.end,
             signedOffset(wave, peakAt(wave.layout, span.begin)),
             signedOffset(wave, peakAt(wave.layout, span.end)), frame);
  }
}

// How far to move `knot` along `direction` so that it ends `amplitude` away from its own
// contour: `amplitude` itself, except next to a sharp convex corner of the icon, where the other
// side of the corner comes closer than the knot point; there the translation grows (secant
// steps, at most kMaxCornerStretch times the amplitude) until the distance is the amplitude.
double translationForDistance(const Point2& knot, const Point2& direction, double amplitude,
                              const Polyline& contour) {
  if (!(amplitude > 0.0)) return 0.0;
  double t = amplitude;
  for (int step = 0; step < kCornerSteps; ++step) {
    const double shortfall = amplitude - distanceToPolyline(knot + t * direction, contour);
    if (shortfall < kCornerTolerance * amplitude) break;
    t = std::min(t + shortfall, kMaxCornerStretch * amplitude);
  }
  return t;
}

std::vector<Point2> targetsOf(const ContourWave& wave) {
  std::vector<Point2> targets;
  for (std::size_t i = 0; i < wave.knot_points.size(); ++i) {
    targets.push_back(wave.knot_points[i] + wave.translations[i] * wave.directions[i]);
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
  return sparseFowlerBartels(fit, constraints);
}

// Index of the layout peak nearest to `arc_length` (peaks are sorted by arc length).
std::size_t nearestPeak(const WaveLayout& layout, double arc_length) {
  const auto upper =
      std::lower_bound(layout.peaks.begin(), layout.peaks.end(), arc_length,
                       [](const WavePeak& peak, double l) { return peak.arc_length < l; });
  if (upper == layout.peaks.begin()) return 0;
  if (upper == layout.peaks.end()) return layout.peaks.size() - 1;
  const std::size_t after = upper - layout.peaks.begin();
  return arc_length - layout.peaks[after - 1].arc_length < upper->arc_length - arc_length
             ? after - 1
             : after;
}

// Rectangle: corner knots of multiplicity 3, every de Boor point first moved with
// its nearest knot point along the normal at its Greville abscissa, so that the plateaus follow
// the offset contour, then Fowler-Bartels meets the knot points exactly and the flanks become
// strips (fitStrips).
BSplineCurve rectangleWave(const BSplineCurve& original, const bspline::ArcLengthTable& table,
                           const ContourFrame& frame, const ContourWave& wave) {
  const BSplineCurve& fit = frame.frame_fit;
  const double area = frame.area;
  BSplineCurve raised = frame.rectangle_fit;
  std::vector<Point2> points = raised.controlPoints();
  const std::vector<double>& knots = raised.knots();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double greville = (knots[i + 1] + knots[i + 2] + knots[i + 3]) / 3.0;
    const std::size_t peak = nearestPeak(wave.layout, greville);
    points[i] +=
        wave.translations[peak] * wave.layout.peaks[peak].sign * outwardNormal(fit, greville, area);
  }
  raised.setControlPoints(points);
  BSplineCurve moved = translateKnotPoints(raised, wave);
  points = moved.controlPoints();
  fitStrips(points, moved, wave, {original, table, fit, area});
  moved.setControlPoints(std::move(points));
  return moved;
}

// Triangle and sawtooth: straight strips between the translated corners.
BSplineCurve stripWave(const ContourWave& wave, const StripFrame& frame) {
  const std::vector<Point2> corners = targetsOf(wave);
  std::vector<Point2> points{corners.front()};
  for (std::size_t i = 1; i < corners.size(); ++i) points.insert(points.end(), 3, corners[i]);
  BSplineCurve curve(3, knotVector(wave.layout), points);
  fitStrips(points, curve, wave, frame);
  curve.setControlPoints(std::move(points));
  return curve;
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
  // Normal equations with the banded N^T N (sparse Cholesky): the least-squares minimiser
  // that ELSPIA converges to (omega = 0), solved directly; far faster than sparse QR here.
  Eigen::MatrixX2d points(lengths.size(), 2);
  for (std::size_t i = 0; i < lengths.size(); ++i) {
    points.row(i) = original.pointAt(table.parameterAt(lengths[i])).transpose();
  }
  const BSplineCurve basis(3, knots, std::vector<Point2>(knots.size() - 4, Point2::Zero()));
  const Eigen::SparseMatrix<double> n = bspline::collocationMatrix(basis, lengths);
  const Eigen::SparseMatrix<double> normal = n.transpose() * n;
  const Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> solver(normal);
  if (solver.info() != Eigen::Success) {
    throw std::invalid_argument("fitOnArcLength: the knot spans are not all covered by samples");
  }
  const Eigen::MatrixX2d control = solver.solve(n.transpose() * points);
  std::vector<Point2> control_points(control.rows());
  for (int i = 0; i < control.rows(); ++i) control_points[i] = control.row(i).transpose();
  return BSplineCurve(3, knots, std::move(control_points));
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

ContourFrame contourFrame(const BSplineCurve& original, const bspline::ArcLengthTable& table,
                          Waveform waveform, int wave_count) {
  if (!original.isClosed(1e-6)) throw std::invalid_argument("modifyContour: contour is not closed");
  ContourFrame frame{waveLayout(waveform, wave_count, table.totalLength()), original, 0.0,
                     original};
  // The smooth fit with single knots every quarter period (the sine's layout) is the sine's base
  // and gives every waveform its normals: the least-squares ringing next to the icon's own
  // corners dies out within a few such short spans, whereas the half-period spans of the sharp
  // layouts would carry it far along the contour.
  frame.frame_fit = fitOnArcLength(
      original, table,
      withContourCorners(knotVector(waveLayout(Waveform::Sine, wave_count, table.totalLength())),
                         original, table));
  frame.area = bspline::signedArea(frame.frame_fit);
  if (waveform == Waveform::Rectangle) {
    // Fitting on the final knot vector gives the same curve space as raising the corner knots of
    // the smooth fit by knot insertion, without Boehm's O(n) copy per inserted knot.
    frame.rectangle_fit = fitOnArcLength(
        original, table, withContourCorners(knotVector(frame.layout), original, table));
  }
  return frame;
}

ContourWave modifyContour(const ContourFrame& frame, const BSplineCurve& original,
                          const bspline::ArcLengthTable& table, double amplitude,
                          const SkeletonGuard* guard, const std::vector<double>& caps,
                          bool stretch_at_corners) {
  ContourWave wave{original, frame.layout, {}, {}, {}, {}, {}};
  const BSplineCurve& frame_fit = frame.frame_fit;
  const double area = frame.area;
  Polyline contour_line;
  if (stretch_at_corners) {
    for (double u : table.parameters()) contour_line.push_back(original.pointAt(u));
  }
  for (const WavePeak& peak : wave.layout.peaks) {
    const bool closing = peak.arc_length >= wave.layout.length;
    // The closing point repeats the first: same point, direction and amplitude.
    if (closing && !wave.knot_points.empty()) {
      wave.knot_points.push_back(wave.knot_points.front());
      wave.directions.push_back(wave.directions.front());
      wave.guarded.push_back(wave.guarded.front());
      wave.capped.push_back(wave.capped.front());
      wave.translations.push_back(wave.translations.front());
      continue;
    }
    const Point2 knot = original.pointAt(table.parameterAt(peak.arc_length));
    const Point2 direction = peak.sign * outwardNormal(frame_fit, peak.arc_length, area);
    wave.knot_points.push_back(knot);
    wave.directions.push_back(direction);
    GuardResult allowed = guard ? guard->limit(knot, direction, amplitude)
                                : GuardResult{std::max(amplitude, 0.0), false, 0};
    const std::size_t i = wave.guarded.size();
    const bool capped = i < caps.size() && caps[i] < allowed.amplitude;
    if (capped) allowed.amplitude = std::max(caps[i], 0.0);
    wave.guarded.push_back(allowed);
    wave.capped.push_back(capped);
    wave.translations.push_back(
        stretch_at_corners
            ? translationForDistance(knot, direction, allowed.amplitude, contour_line)
            : allowed.amplitude);
  }
  switch (wave.layout.waveform) {
    case Waveform::Sine:
      wave.curve = translateKnotPoints(frame_fit, wave);
      break;
    case Waveform::Rectangle:
      wave.curve = rectangleWave(original, table, frame, wave);
      break;
    case Waveform::Triangle:
    case Waveform::Sawtooth:
      wave.curve = stripWave(wave, {original, table, frame_fit, area});
      break;
  }
  return wave;
}

ContourWave modifyContour(const BSplineCurve& original, const bspline::ArcLengthTable& table,
                          Waveform waveform, int wave_count, double amplitude,
                          const SkeletonGuard* guard, const std::vector<double>& caps,
                          bool stretch_at_corners) {
  return modifyContour(contourFrame(original, table, waveform, wave_count), original, table,
                       amplitude, guard, caps, stretch_at_corners);
}

}  // namespace pacemod
}  // namespace vicc_glyphs
