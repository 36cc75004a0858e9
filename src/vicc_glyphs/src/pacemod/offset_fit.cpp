#include "offset_fit.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "vicc_glyphs/bspline/fitting.hpp"
#include "vicc_glyphs/pacemod/polyline.hpp"
#include "wave_strips.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace detail {
namespace {

constexpr int kSamplesPerSpan = 8;
constexpr double kOnCorner = 1e-3;  // px of arc length
// Next to a corner the samples within this multiple of the stretch its offset contour needs
// (the swallowtail inside its angle, |w| outside) follow the corner's offset contour ...
constexpr double kSpreadOver = 2.0;
// ... but at most this fraction of the way to the next knot: the wave's own offset changes
// from knot to knot.
constexpr double kRoomFraction = 0.5;
constexpr int kBisectionSteps = 24;
constexpr int kOffsetProbes = 8;
constexpr double kSearchMargin = 1.5;

}  // namespace

double OffsetFit::knotGap(double at, int side) const {
  if (side > 0) {
    const auto next = std::upper_bound(knots_.begin(), knots_.end(), at + kOnCorner);
    return next == knots_.end() ? 0.0 : *next - at;
  }
  const auto first = std::lower_bound(knots_.begin(), knots_.end(), at - kOnCorner);
  return first == knots_.begin() ? 0.0 : at - *(first - 1);
}

OffsetFit::OffsetFit(const bspline::BSplineCurve& original, const bspline::ArcLengthTable& table,
                     std::vector<double> knots, const std::vector<ContourCorner>& corners,
                     double area)
    : knots_(std::move(knots)), frame_{original, table, area}, corners_(corners) {
  std::vector<double> lengths;
  lengths.reserve(knots_.size() * kSamplesPerSpan);
  for (std::size_t i = 3; i + 4 < knots_.size(); ++i) {
    if (knots_[i + 1] <= knots_[i]) continue;
    for (int k = 0; k < kSamplesPerSpan; ++k) {
      lengths.push_back(knots_[i] + (knots_[i + 1] - knots_[i]) * k / kSamplesPerSpan);
    }
  }
  lengths.push_back(knots_.back());
  const double end = knots_.back();
  const std::vector<ContourSample> on_contour = frame_.samples(lengths);
  // Per corner the room on its side before and after it (the closing corner's before is at L).
  std::vector<std::pair<double, double>> room;
  for (const ContourCorner& corner : corners_) {
    const double at = corner.arc_length;
    room.push_back(
        {kRoomFraction * knotGap(at == 0.0 ? end : at, -1), kRoomFraction * knotGap(at, 1)});
  }
  const std::vector<int> nearest = nearestCorners(corners_, lengths, end);
  samples_.reserve(lengths.size());
  for (std::size_t i = 0; i < lengths.size(); ++i) {
    const double l = lengths[i];
    Sample sample{l, on_contour[i].point, on_contour[i].normal, nearest[i], 0, 0.0};
    if (sample.corner >= 0) {
      // The closing corner (at 0) is also the one at L.
      const double arc_length = corners_[sample.corner].arc_length;
      const double at = arc_length == 0.0 && l > 0.5 * end ? end : arc_length;
      sample.side = std::abs(l - at) < kOnCorner ? 0 : (l < at ? -1 : 1);
      if (sample.side != 0) {
        sample.room = sample.side < 0 ? room[sample.corner].first : room[sample.corner].second;
      }
    }
    samples_.push_back(sample);
  }
  // Half the way to the neighbouring corners (the whole contour's half for a single one).
  for (std::size_t c = 0; c < corners_.size(); ++c) {
    const std::size_t n = corners_.size();
    const double before = corners_[(c + n - 1) % n].arc_length;
    const double after = corners_[(c + 1) % n].arc_length;
    const double at = corners_[c].arc_length;
    const double to_before = n == 1 ? end : std::fmod(at - before + end, end);
    const double to_after = n == 1 ? end : std::fmod(after - at + end, end);
    reach_.push_back({0.5 * to_before, 0.5 * to_after});
  }
  const bspline::BSplineCurve basis(3, knots_,
                                    std::vector<Point2>(knots_.size() - 4, Point2::Zero()));
  // Normal equations with the banded N^T N (Cholesky): the least-squares minimiser that ELSPIA
  // converges to (omega = 0), solved directly; far faster than sparse QR here.
  solver_ = std::make_shared<const bspline::CubicLeastSquares>(basis, lengths);
}

Point2 OffsetFit::sideOffset(int c, int side, double distance, const Offset& offset) const {
  const double end = knots_.back();
  double l = corners_[c].arc_length + side * distance;
  if (l < 0.0) l += end;
  if (l > end) l -= end;
  return frame_.offsetPoint(l, offset(l));
}

double OffsetFit::meetingDistance(int c, int side, const Offset& offset) const {
  const ContourCorner& corner = corners_[c];
  // Search as far as the largest offset near the corner could carry past the bisector on
  // straight sides (and a margin for curved ones), at most half the way to the next corner.
  const double most = side < 0 ? reach_[c].first : reach_[c].second;
  double largest = 0.0;
  for (int k = 0; k <= kOffsetProbes; ++k) {
    const double l = corner.arc_length + side * most * k / kOffsetProbes;
    const double end = knots_.back();
    largest = std::max(largest, std::abs(offset(l < 0.0 ? l + end : (l > end ? l - end : l))));
  }
  const double limit =
      std::min(most, kSearchMargin * corner.swallowtail(corner.inner_sign * largest));
  auto past = [&](double s) { return corner.pastBisector(sideOffset(c, side, s, offset), side); };
  if (past(limit)) return limit;
  double low = 0.0, high = limit;
  for (int step = 0; step < kBisectionSteps; ++step) {
    const double mid = 0.5 * (low + high);
    (past(mid) ? low : high) = mid;
  }
  return high;
}

double OffsetFit::spreadDistance(int c, int side, double meeting) const {
  return std::min(kSpreadOver * meeting, side < 0 ? reach_[c].first : reach_[c].second);
}

OffsetFit::CornerPassage OffsetFit::cornerPassage(const Offset& offset) const {
  CornerPassage passage{std::vector<std::pair<double, double>>(corners_.size(), {0.0, 0.0}), {}};
  for (std::size_t c = 0; c < corners_.size(); ++c) {
    const ContourCorner& corner = corners_[c];
    const double w = offset(corner.arc_length);
    if (!corner.inside(w)) {
      passage.targets.push_back(corner.offsetPoint(w));
      continue;
    }
    const int i = static_cast<int>(c);
    const double before = meetingDistance(i, -1, offset), after = meetingDistance(i, 1, offset);
    passage.meeting[c] = {before, after};
    passage.targets.push_back(
        0.5 * (sideOffset(i, -1, before, offset) + sideOffset(i, 1, after, offset)));
  }
  return passage;
}

Point2 OffsetFit::cornerPath(int c, int side, double distance, double spread, double meeting,
                             const Point2& target, const Offset& offset) const {
  const ContourCorner& corner = corners_[c];
  const double w_corner = offset(corner.arc_length);
  if (corner.inside(w_corner)) {
    // [0, spread) from the corner onto [meeting, spread) of the side: the part left of it.
    if (spread <= meeting) return target;
    return sideOffset(c, side, meeting + distance * (spread - meeting) / spread, offset);
  }
  // Outside the angle: the side's offset, then half the arc of radius |w| around the corner
  // to its offset point, over [spread, 0) of arc length.
  const double turn = 2.0 * std::acos(std::clamp(corner.half_turn_cosine, 0.0, 1.0));
  const double half_arc = 0.5 * std::abs(w_corner) * turn;
  const double along = (spread - distance) / spread * (spread + half_arc);  // from the far end
  if (along <= spread) return sideOffset(c, side, spread - along, offset);
  // The side's normal turned by `angle` towards the bisector.
  const double angle = (along - spread) / std::abs(w_corner);
  const Point2 normal = side < 0 ? corner.normal_before : corner.normal_after;
  const double direction = cross(normal, corner.bisector) >= 0.0 ? 1.0 : -1.0;
  const double co = std::cos(angle), si = direction * std::sin(angle);
  return corner.point +
         w_corner * Point2(co * normal.x() - si * normal.y(), si * normal.x() + co * normal.y());
}

bspline::BSplineCurve OffsetFit::fit(const Offset& offset, const CornerPassage& passage) const {
  const double end = knots_.back();
  // Per corner and side: how far the offset contour takes over (inside: from the meeting point).
  const std::vector<std::pair<double, double>>& meeting = passage.meeting;
  const std::vector<Point2>& corner_targets = passage.targets;
  std::vector<double> needs(corners_.size(), 0.0);
  for (std::size_t c = 0; c < corners_.size(); ++c) {
    const double w = offset(corners_[c].arc_length);
    if (!corners_[c].inside(w)) needs[c] = std::abs(w);
  }
  Eigen::MatrixX2d targets(samples_.size(), 2);
  for (std::size_t i = 0; i < samples_.size(); ++i) {
    const Sample& s = samples_[i];
    Point2 q = s.point + offset(s.arc_length) * s.normal;
    if (s.corner >= 0) {
      // The closing corner is at 0 and at L.
      const double distance = cyclicDistance(s.arc_length, corners_[s.corner].arc_length, end);
      const double met = s.side < 0 ? meeting[s.corner].first : meeting[s.corner].second;
      // Inside the angle the whole swallowed stretch has to be spread; outside, the arc takes
      // over at most half the way to the next knot.
      const double spread = met > 0.0 ? spreadDistance(s.corner, s.side, met)
                                      : std::min(kSpreadOver * needs[s.corner], s.room);
      if (s.side == 0) {
        q = corner_targets[s.corner];
      } else if (distance < spread) {
        q = cornerPath(s.corner, s.side, distance, spread, met, corner_targets[s.corner], offset);
      }
    }
    targets.row(static_cast<int>(i)) = q.transpose();
  }
  return bspline::BSplineCurve(3, knots_, solver_->solvePoints(targets));
}

}  // namespace detail
}  // namespace pacemod
}  // namespace vicc_glyphs
