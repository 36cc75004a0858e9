#include "vicc_glyphs/pacemod/polyline.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace vicc_glyphs {
namespace pacemod {

Polyline sampleCurve(const DiffusionCurve& curve, int per_segment) {
  const int segments = curve.segmentCount();
  Polyline line;
  if (segments < 1) return line;
  per_segment = std::max(per_segment, 1);
  for (int i = 0; i < segments * per_segment; ++i) {
    line.push_back(curve.pointAt(static_cast<double>(i) / per_segment));
  }
  line.push_back(curve.pointAt(segments));
  return line;
}

double distanceToPolyline(const Point2& point, const Polyline& line) {
  if (line.empty()) return std::numeric_limits<double>::infinity();
  double best = (point - line.front()).squaredNorm();
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    const Point2 d = line[i + 1] - line[i];
    const double length2 = d.squaredNorm();
    const double t = length2 > 0.0 ? std::clamp((point - line[i]).dot(d) / length2, 0.0, 1.0) : 0.0;
    best = std::min(best, (point - line[i] - t * d).squaredNorm());
  }
  return std::sqrt(best);
}

namespace {

// The ends exactly (a + 1 * (b - a) may miss b by a rounding): callers tell a vertex by them.
Point2 nearestOnSegment(const Point2& point, const Point2& a, const Point2& b) {
  const Point2 d = b - a;
  const double length2 = d.squaredNorm();
  const double t = length2 > 0.0 ? (point - a).dot(d) / length2 : 0.0;
  if (!(t > 0.0)) return a;
  if (t >= 1.0) return b;
  return a + t * d;
}

double squaredSegmentDistance(const Point2& point, const Point2& a, const Point2& b) {
  return (point - nearestOnSegment(point, a, b)).squaredNorm();
}

}  // namespace

PolylineDistance::PolylineDistance(const Polyline& line, double cell) : line_(line), cell_(cell) {
  if (!(cell > 0.0) || !std::isfinite(cell)) {
    throw std::invalid_argument("PolylineDistance: the cell size must be a finite number > 0");
  }
  Point2 lo = Point2::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  const auto finite = [&](int i) { return line[i].allFinite() && line[i + 1].allFinite(); };
  const int segments = static_cast<int>(line.size()) - 1;
  for (int i = 0; i < segments; ++i) {
    if (!finite(i)) continue;
    lo = lo.cwiseMin(line[i].cwiseMin(line[i + 1]));
    hi = hi.cwiseMax(line[i].cwiseMax(line[i + 1]));
  }
  if (!(lo.x() <= hi.x())) return;  // no finite segment
  // A coarser grid finds the same nearest points; only the segments tried per query grow.
  const auto cells = [&](double size) {
    return (std::floor(hi.x() / size) - std::floor(lo.x() / size) + 1.0) *
           (std::floor(hi.y() / size) - std::floor(lo.y() / size) + 1.0);
  };
  while (!(cells(cell_) <= kMaxCells)) cell_ *= 2.0;
  min_x_ = static_cast<long long>(std::floor(lo.x() / cell_));
  min_y_ = static_cast<long long>(std::floor(lo.y() / cell_));
  max_x_ = static_cast<long long>(std::floor(hi.x() / cell_));
  max_y_ = static_cast<long long>(std::floor(hi.y() / cell_));
  const long long width = max_x_ - min_x_ + 1;
  // Segment indices per cell, row-major (a counting sort: cell c holds
  // segments_[start_[c]] ... segments_[start_[c + 1] - 1]).
  const auto forEachCell = [&](int i, auto&& visit) {
    const Point2 a = line[i].cwiseMin(line[i + 1]) / cell_,
                 b = line[i].cwiseMax(line[i + 1]) / cell_;
    for (long long y = std::floor(a.y()); y <= static_cast<long long>(std::floor(b.y())); ++y) {
      for (long long x = std::floor(a.x()); x <= static_cast<long long>(std::floor(b.x())); ++x) {
        visit((y - min_y_) * width + (x - min_x_));
      }
    }
  };
  start_.assign(static_cast<std::size_t>(width * (max_y_ - min_y_ + 1)) + 1, 0);
  for (int i = 0; i < segments; ++i) {
    if (finite(i)) forEachCell(i, [&](long long c) { ++start_[c]; });
  }
  for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  segments_.resize(start_.back());
  for (int i = segments - 1; i >= 0; --i) {  // backwards: each cell keeps increasing indices
    if (finite(i)) forEachCell(i, [&](long long c) { segments_[--start_[c]] = i; });
  }
}

double PolylineDistance::operator()(const Point2& point) const {
  if (segments_.empty()) return distanceToPolyline(point, line_);
  const int segment = nearestSegment(point);
  if (segment < 0) return std::numeric_limits<double>::infinity();
  return std::sqrt(squaredSegmentDistance(point, line_[segment], line_[segment + 1]));
}

Point2 PolylineDistance::nearest(const Point2& point, int* segment_index) const {
  const int segment = segments_.empty() ? -1 : nearestSegment(point);
  if (segment_index) *segment_index = segment;
  if (segment < 0) {
    return line_.size() == 1 && point.allFinite() ? line_.front() : Point2::Constant(NAN);
  }
  return nearestOnSegment(point, line_[segment], line_[segment + 1]);
}

int PolylineDistance::nearestSegment(const Point2& point) const {
  const Point2 at = point / cell_;
  if (!at.allFinite()) return -1;
  if (at.cwiseAbs().maxCoeff() > kFarCells) return nearestSegmentScanned(point);
  const long long cx = std::floor(at.x()), cy = std::floor(at.y());
  // Rings nearer than the grid hold none of its cells, rings beyond this one none either.
  const long long first_ring = std::max({0LL, min_x_ - cx, cx - max_x_, min_y_ - cy, cy - max_y_});
  const long long last_ring = std::max(
      {std::abs(cx - min_x_), std::abs(cx - max_x_), std::abs(cy - min_y_), std::abs(cy - max_y_)});
  const long long width = max_x_ - min_x_ + 1;
  double best = std::numeric_limits<double>::infinity();
  int best_segment = -1;
  const auto visit = [&](long long x, long long y) {
    const long long c = (y - min_y_) * width + (x - min_x_);
    for (int k = start_[c]; k < start_[c + 1]; ++k) {
      const int i = segments_[k];
      const double distance2 = squaredSegmentDistance(point, line_[i], line_[i + 1]);
      if (distance2 < best) best = distance2, best_segment = i;
    }
  };
  for (long long r = first_ring; r <= last_ring; ++r) {
    const long long y0 = std::max(cy - r, min_y_), y1 = std::min(cy + r, max_y_);
    for (long long x = std::max(cx - r, min_x_); x <= std::min(cx + r, max_x_); ++x) {
      if (x == cx - r || x == cx + r) {  // the ring's whole column
        for (long long y = y0; y <= y1; ++y) visit(x, y);
      } else {  // its two cells in this column
        if (cy - r >= min_y_) visit(x, cy - r);
        if (r > 0 && cy + r <= max_y_) visit(x, cy + r);
      }
    }
    // Any cell of ring r + 1 is at least r cells away from the point.
    if (best <= (r * cell_) * (r * cell_)) break;
  }
  return best_segment;
}

int PolylineDistance::nearestSegmentScanned(const Point2& point) const {
  double best = std::numeric_limits<double>::infinity();
  int best_segment = -1;
  for (int i = 0; i + 1 < static_cast<int>(line_.size()); ++i) {
    const double distance2 = squaredSegmentDistance(point, line_[i], line_[i + 1]);
    if (distance2 < best) best = distance2, best_segment = i;
  }
  return best_segment;
}

double polylineArea(const Polyline& line) {
  double area = 0.0;
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    area += line[i].x() * line[i + 1].y() - line[i + 1].x() * line[i].y();
  }
  if (!line.empty())
    area += line.back().x() * line.front().y() - line.front().x() * line.back().y();
  return 0.5 * area;
}

bool isClosedPolyline(const Polyline& line) {
  return line.size() >= 5 && (line.front() - line.back()).norm() <= 1e-6;
}

double cyclicOffset(double from, double to, double length) {
  double d = to - from;
  if (d > 0.5 * length) d -= length;
  if (d < -0.5 * length) d += length;
  return d;
}

double cyclicDistance(double a, double b, double length) {
  const double d = std::abs(a - b);
  return std::min(d, length - d);
}

bool insidePolygon(const Point2& point, const Polyline& line) {
  bool inside = false;
  for (std::size_t i = 0, j = line.size() - 1; i < line.size(); j = i++) {
    const Point2& a = line[i];
    const Point2& b = line[j];
    if ((a.y() > point.y()) != (b.y() > point.y()) &&
        point.x() < (b.x() - a.x()) * (point.y() - a.y()) / (b.y() - a.y()) + a.x()) {
      inside = !inside;
    }
  }
  return inside;
}

}  // namespace pacemod
}  // namespace vicc_glyphs
