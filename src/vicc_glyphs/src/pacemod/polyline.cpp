#include "vicc_glyphs/pacemod/polyline.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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

long long cellKey(long long x, long long y) { return (x << 32) ^ (y & 0xffffffffLL); }

Point2 nearestOnSegment(const Point2& point, const Point2& a, const Point2& b) {
  const Point2 d = b - a;
  const double length2 = d.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((point - a).dot(d) / length2, 0.0, 1.0) : 0.0;
  return a + t * d;
}

double squaredSegmentDistance(const Point2& point, const Point2& a, const Point2& b) {
  return (point - nearestOnSegment(point, a, b)).squaredNorm();
}

}  // namespace

PolylineDistance::PolylineDistance(const Polyline& line, double cell) : line_(line), cell_(cell) {
  bool first = true;
  for (int i = 0; i + 1 < static_cast<int>(line.size()); ++i) {
    const Point2 lo = line[i].cwiseMin(line[i + 1]) / cell;
    const Point2 hi = line[i].cwiseMax(line[i + 1]) / cell;
    if (!lo.allFinite() || !hi.allFinite()) continue;
    const long long x0 = std::floor(lo.x()), y0 = std::floor(lo.y());
    const long long x1 = std::floor(hi.x()), y1 = std::floor(hi.y());
    min_x_ = first ? x0 : std::min(min_x_, x0);
    min_y_ = first ? y0 : std::min(min_y_, y0);
    max_x_ = first ? x1 : std::max(max_x_, x1);
    max_y_ = first ? y1 : std::max(max_y_, y1);
    first = false;
    for (long long x = x0; x <= x1; ++x) {
      for (long long y = y0; y <= y1; ++y) buckets_[cellKey(x, y)].push_back(i);
    }
  }
}

double PolylineDistance::operator()(const Point2& point) const {
  if (buckets_.empty()) return distanceToPolyline(point, line_);
  const int segment = nearestSegment(point);
  if (segment < 0) return std::numeric_limits<double>::infinity();
  return std::sqrt(squaredSegmentDistance(point, line_[segment], line_[segment + 1]));
}

Point2 PolylineDistance::nearest(const Point2& point, int* segment_index) const {
  const int segment = buckets_.empty() ? -1 : nearestSegment(point);
  if (segment_index) *segment_index = segment;
  if (segment < 0) {
    return line_.size() == 1 && point.allFinite() ? line_.front() : Point2::Constant(NAN);
  }
  return nearestOnSegment(point, line_[segment], line_[segment + 1]);
}

int PolylineDistance::nearestSegment(const Point2& point) const {
  const Point2 at = point / cell_;
  if (!at.allFinite()) return -1;
  const long long cx = std::floor(at.x()), cy = std::floor(at.y());
  // Rings beyond this one hold no cell of the polyline's bounding box.
  const long long last_ring = std::max(
      {std::abs(cx - min_x_), std::abs(cx - max_x_), std::abs(cy - min_y_), std::abs(cy - max_y_)});
  double best = std::numeric_limits<double>::infinity();
  int best_segment = -1;
  for (long long r = 0; r <= last_ring; ++r) {
    for (long long x = cx - r; x <= cx + r; ++x) {
      const bool side = x == cx - r || x == cx + r;  // whole column; else its two ring cells
      for (long long y = cy - r; y <= cy + r; y += side || r == 0 ? 1 : 2 * r) {
        const auto found = buckets_.find(cellKey(x, y));
        if (found == buckets_.end()) continue;
        for (int i : found->second) {
          const double distance2 = squaredSegmentDistance(point, line_[i], line_[i + 1]);
          if (distance2 < best) best = distance2, best_segment = i;
        }
      }
    }
    // Any cell of ring r + 1 is at least r cells away from the point.
    if (best <= (r * cell_) * (r * cell_)) break;
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
