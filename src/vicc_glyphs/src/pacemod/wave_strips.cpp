#include "wave_strips.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

namespace vicc_glyphs {
namespace pacemod {
namespace detail {
namespace {

constexpr int kStripSamples = 9;
constexpr int kArcSamples = 4;         // per half arc around an icon corner
constexpr double kNormalChord = 0.25;  // px of arc length to either side

}  // namespace

Point2 OffsetFrame::normal(double l) const {
  // The chord over a small stretch: sub-pixel steps of an imported polygon (and zero-length
  // handles) do not turn the offset by their own angle.
  const double end = table.totalLength();
  return normalOfChord(original.pointAt(table.parameterAt(std::max(l - kNormalChord, 0.0))),
                       original.pointAt(table.parameterAt(std::min(l + kNormalChord, end))), l);
}

Point2 OffsetFrame::normalOfChord(const Point2& before, const Point2& after, double l) const {
  const Point2 d = after - before;
  if (d.norm() > 1e-9) return outwardNormalOf(d, area);
  return outwardNormalOf(original.derivativeAt(table.parameterAt(l)), area);
}

std::vector<ContourSample> OffsetFrame::samples(const std::vector<double>& lengths) const {
  const double end = table.totalLength();
  std::vector<double> before(lengths.size()), after(lengths.size());
  for (std::size_t i = 0; i < lengths.size(); ++i) {
    before[i] = std::max(lengths[i] - kNormalChord, 0.0);
    after[i] = std::min(lengths[i] + kNormalChord, end);
  }
  const std::vector<Point2> points = original.pointsAt(table.parametersAt(lengths));
  const std::vector<Point2> behind = original.pointsAt(table.parametersAt(before));
  const std::vector<Point2> ahead = original.pointsAt(table.parametersAt(after));
  std::vector<ContourSample> result(lengths.size());
  for (std::size_t i = 0; i < lengths.size(); ++i) {
    result[i] = {points[i], normalOfChord(behind[i], ahead[i], lengths[i])};
  }
  return result;
}

Point2 OffsetFrame::offsetPoint(double l, double w) const {
  return original.pointAt(table.parameterAt(l)) + w * normal(l);
}

ContourSample OffsetFrame::sample(double l) const {
  return {original.pointAt(table.parameterAt(l)), normal(l)};
}

int StripPiece::cornerSide(bool at_begin) const {
  if (at_begin) return corner_arc_at_begin >= l1 ? -1 : 1;
  return corner_arc_at_end <= l0 ? 1 : -1;
}

std::vector<ContourSample> stripSamples(const OffsetFrame& frame, double l0, double l1) {
  std::vector<double> lengths;
  for (int k = 1; k <= kStripSamples; ++k) {
    const double t = static_cast<double>(k) / (kStripSamples + 1);
    lengths.push_back(l0 + t * (l1 - l0));
  }
  if (l1 < l0) std::reverse(lengths.begin(), lengths.end());
  std::vector<ContourSample> samples = frame.samples(lengths);
  if (l1 < l0) std::reverse(samples.begin(), samples.end());
  return samples;
}

// Points of the circular arc of radius |w| around `corner` between its offset point (on the
// bisector) and the offset of the side after it (`side` +1) or before it (-1), excluding both
// ends, ordered along the contour: the offset contour outside the corner's angle.
std::vector<Point2> outerArc(const ContourCorner& corner, double w, int side) {
  std::vector<Point2> arc;
  if (corner.inside(w) || w == 0.0) return arc;
  const Point2 normal = side > 0 ? corner.normal_after : corner.normal_before;
  const double direction = cross(corner.bisector, normal) >= 0.0 ? 1.0 : -1.0;
  const double half_turn = std::acos(std::clamp(corner.half_turn_cosine, 0.0, 1.0));
  for (int k = 1; k < kArcSamples; ++k) {
    // From the bisector towards the side's normal (after), or back (before).
    const double t = side > 0 ? double(k) / kArcSamples : 1.0 - double(k) / kArcSamples;
    const double angle = direction * t * half_turn;
    const double c = std::cos(angle), s = std::sin(angle);
    const Point2 b = corner.bisector;
    arc.push_back(corner.point + w * Point2(c * b.x() - s * b.y(), s * b.x() + c * b.y()));
  }
  return arc;
}

StripDeviation fitStrip(std::vector<Point2>& points, int first, const StripPiece& piece,
                        const OffsetFrame& frame) {
  return fitStrip(points, first, piece, stripSamples(frame, piece.l0, piece.l1));
}

StripDeviation fitStrip(std::vector<Point2>& points, int first, const StripPiece& piece,
                        const std::vector<ContourSample>& samples) {
  const Point2 p0 = points[first], p3 = points[first + 3];
  // The offset path with the curve parameter of each point: the arc-length fraction along the
  // piece, or (once a corner changed the path) the chord length along it.
  std::vector<Point2> path{p0};
  std::vector<double> at{0.0};
  bool by_chord = false;
  auto addArc = [&](const ContourCorner* corner, double w, int side) {
    if (!corner) return;
    for (const Point2& q : outerArc(*corner, w, side)) {
      path.push_back(q);
      at.push_back(side > 0 ? 0.0 : 1.0);
      by_chord = true;
    }
  };
  addArc(piece.corner_at_begin, piece.w0, +1);
  const int count = static_cast<int>(samples.size());
  auto past = [&](bool at_begin, const Point2& q) {
    const ContourCorner* corner = at_begin ? piece.corner_at_begin : piece.corner_at_end;
    return corner && corner->pastBisector(q, piece.cornerSide(at_begin));
  };
  for (int k = 1; k <= count; ++k) {
    const double t = static_cast<double>(k) / (count + 1);
    const ContourSample& sample = samples[k - 1];
    const Point2 q = sample.point + ((1 - t) * piece.w0 + t * piece.w1) * sample.normal;
    if (past(true, q) || past(false, q)) {
      by_chord = true;
      continue;
    }
    path.push_back(q);
    at.push_back(t);
  }
  addArc(piece.corner_at_end, piece.w1, -1);
  path.push_back(p3);
  at.push_back(1.0);
  if (by_chord) {
    at.assign(1, 0.0);
    for (std::size_t i = 1; i < path.size(); ++i) {
      at.push_back(at.back() + (path[i] - path[i - 1]).norm());
    }
    for (double& t : at) t = at.back() > 0.0 ? t / at.back() : 0.0;
  }
  if (path.size() < 4 || !(at.back() > 0.0)) {  // too little left: the straight line
    points[first + 1] = p0 + (p3 - p0) / 3.0;
    points[first + 2] = p0 + 2.0 * (p3 - p0) / 3.0;
    return {};
  }
  Eigen::Matrix2d normal = Eigen::Matrix2d::Zero();
  Eigen::Matrix2d rhs = Eigen::Matrix2d::Zero();
  for (std::size_t i = 1; i + 1 < path.size(); ++i) {
    const double t = at[i];
    const double b0 = (1 - t) * (1 - t) * (1 - t), b1 = 3 * t * (1 - t) * (1 - t),
                 b2 = 3 * t * t * (1 - t), b3 = t * t * t;
    const Eigen::Vector2d basis(b1, b2);
    normal += basis * basis.transpose();
    rhs += basis * (path[i] - b0 * p0 - b3 * p3).transpose();
  }
  const Eigen::Matrix2d inner = normal.ldlt().solve(rhs);
  const Point2 p1 = inner.row(0).transpose(), p2 = inner.row(1).transpose();
  points[first + 1] = p1;
  points[first + 2] = p2;
  // The half away from a single icon corner: t from 0.5 on after one at the beginning, up to
  // 0.5 before one at the end.
  const bool one_corner = (piece.corner_at_begin != nullptr) != (piece.corner_at_end != nullptr);
  const double far_sign = piece.corner_at_begin ? 1.0 : -1.0;
  StripDeviation deviation;
  for (std::size_t i = 1; i + 1 < path.size(); ++i) {
    const double t = at[i], s = 1.0 - t;
    const Point2 fitted = s * s * s * p0 + 3 * t * s * s * p1 + 3 * t * t * s * p2 + t * t * t * p3;
    const double distance = (fitted - path[i]).norm();
    deviation.largest = std::max(deviation.largest, distance);
    if (one_corner && far_sign * (t - 0.5) >= 0.0) {
      deviation.away_from_corner = std::max(deviation.away_from_corner, distance);
    }
  }
  return deviation;
}

}  // namespace detail
}  // namespace pacemod
}  // namespace vicc_glyphs
