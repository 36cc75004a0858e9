#include "vicc_glyphs/pacemod/polyline.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

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

PolylineSetDistance::PolylineSetDistance(std::vector<const Polyline*> lines, double cell)
    : lines_(std::move(lines)), cell_(cell) {
  if (!(cell > 0.0) || !std::isfinite(cell)) {
    throw std::invalid_argument("PolylineDistance: the cell size must be a finite number > 0");
  }
  const auto finite = [&](const Polyline& line, int i) {
    return line[i].allFinite() && line[i + 1].allFinite();
  };
  // Calls visit(line, segment) for every segment with finite ends, last line and segment first.
  const auto forEachSegmentBackwards = [&](auto&& visit) {
    for (int l = static_cast<int>(lines_.size()) - 1; l >= 0; --l) {
      const Polyline& line = *lines_[l];
      for (int i = static_cast<int>(line.size()) - 2; i >= 0; --i) {
        if (finite(line, i)) visit(line, Segment{l, i});
      }
    }
  };
  Point2 lo = Point2::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  forEachSegmentBackwards([&](const Polyline& line, const Segment& s) {
    lo = lo.cwiseMin(line[s.segment].cwiseMin(line[s.segment + 1]));
    hi = hi.cwiseMax(line[s.segment].cwiseMax(line[s.segment + 1]));
  });
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
  // The segments per cell, row-major (a counting sort: cell c holds
  // entries_[start_[c]] ... entries_[start_[c + 1] - 1]).
  const auto forEachCell = [&](const Polyline& line, int i, auto&& visit) {
    const Point2 a = line[i].cwiseMin(line[i + 1]) / cell_,
                 b = line[i].cwiseMax(line[i + 1]) / cell_;
    for (long long y = std::floor(a.y()); y <= static_cast<long long>(std::floor(b.y())); ++y) {
      for (long long x = std::floor(a.x()); x <= static_cast<long long>(std::floor(b.x())); ++x) {
        visit((y - min_y_) * width + (x - min_x_));
      }
    }
  };
  start_.assign(static_cast<std::size_t>(width * (max_y_ - min_y_ + 1)) + 1, 0);
  forEachSegmentBackwards([&](const Polyline& line, const Segment& s) {
    forEachCell(line, s.segment, [&](long long c) { ++start_[c]; });
  });
  for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  entries_.resize(start_.back());
  // Filled backwards: each cell keeps its segments in increasing (line, segment) order.
  forEachSegmentBackwards([&](const Polyline& line, const Segment& s) {
    const Entry entry{line[s.segment], line[s.segment + 1], s};
    forEachCell(line, s.segment, [&](long long c) { entries_[--start_[c]] = entry; });
  });
}

Point2 PolylineSetDistance::nearestOn(const Segment& s, const Point2& point) const {
  const Polyline& line = *lines_[s.line];
  return nearestOnSegment(point, line[s.segment], line[s.segment + 1]);
}

PolylineSetDistance::Segment PolylineSetDistance::nearestSegment(const Point2& point,
                                                                 double radius) const {
  if (entries_.empty() || !(radius > 0.0)) return {};
  const Point2 at = point / cell_;
  if (!at.allFinite()) return {};
  if (at.cwiseAbs().maxCoeff() > kFarCells) return nearestScanned(point, radius);
  const long long cx = std::floor(at.x()), cy = std::floor(at.y());
  // Rings nearer than the grid hold none of its cells, rings beyond this one none either.
  const long long first_ring = std::max({0LL, min_x_ - cx, cx - max_x_, min_y_ - cy, cy - max_y_});
  const long long last_ring = std::max(
      {std::abs(cx - min_x_), std::abs(cx - max_x_), std::abs(cy - min_y_), std::abs(cy - max_y_)});
  const long long width = max_x_ - min_x_ + 1;
  double best = radius * radius;
  Segment best_segment;
  // Squared distance from the point to column (row) x of cells, 0 for its own.
  const auto gap2 = [&](long long cell_index, double coordinate) {
    const double gap =
        std::max({0.0, cell_index * cell_ - coordinate, coordinate - (cell_index + 1) * cell_});
    return gap * gap;
  };
  // A cell nearer than the best so far (none of its segments can be nearer otherwise).
  const auto visit = [&](long long x, long long y, double gap2_x) {
    const long long c = (y - min_y_) * width + (x - min_x_);
    if (start_[c] == start_[c + 1] || gap2_x + gap2(y, point.y()) >= best) return;
    for (int k = start_[c]; k < start_[c + 1]; ++k) {
      const Entry& entry = entries_[k];
      const double distance2 = squaredSegmentDistance(point, entry.a, entry.b);
      if (distance2 < best) best = distance2, best_segment = entry.segment;
    }
  };
  for (long long r = first_ring; r <= last_ring; ++r) {
    const long long y0 = std::max(cy - r, min_y_), y1 = std::min(cy + r, max_y_);
    for (long long x = std::max(cx - r, min_x_); x <= std::min(cx + r, max_x_); ++x) {
      const double gap2_x = gap2(x, point.x());
      if (gap2_x >= best) continue;
      if (x == cx - r || x == cx + r) {  // the ring's whole column
        for (long long y = y0; y <= y1; ++y) visit(x, y, gap2_x);
      } else {  // its two cells in this column
        if (cy - r >= min_y_) visit(x, cy - r, gap2_x);
        if (r > 0 && cy + r <= max_y_) visit(x, cy + r, gap2_x);
      }
    }
    // Any cell of ring r + 1 is at least r cells away from the point.
    if (best <= (r * cell_) * (r * cell_)) break;
  }
  return best_segment;
}

PolylineSetDistance::Segment PolylineSetDistance::nearestScanned(const Point2& point,
                                                                 double radius) const {
  double best = radius * radius;
  Segment best_segment;
  for (int l = 0; l < static_cast<int>(lines_.size()); ++l) {
    for (int i = 0; i + 1 < static_cast<int>(lines_[l]->size()); ++i) {
      const double distance2 = squaredSegmentDistance(point, (*lines_[l])[i], (*lines_[l])[i + 1]);
      if (distance2 < best) best = distance2, best_segment = {l, i};
    }
  }
  return best_segment;
}

PolylineDistance::PolylineDistance(const Polyline& line, double cell)
    : line_(line), segments_({&line}, cell) {}

double PolylineDistance::operator()(const Point2& point) const {
  if (segments_.empty()) return distanceToPolyline(point, line_);
  const PolylineSetDistance::Segment segment = segments_.nearestSegment(point);
  if (segment.line < 0) return std::numeric_limits<double>::infinity();
  return std::sqrt(
      squaredSegmentDistance(point, line_[segment.segment], line_[segment.segment + 1]));
}

Point2 PolylineDistance::nearest(const Point2& point, int* segment_index) const {
  const PolylineSetDistance::Segment segment = segments_.nearestSegment(point);
  if (segment_index) *segment_index = segment.segment;
  if (segment.line < 0) {
    return line_.size() == 1 && point.allFinite() ? line_.front() : Point2::Constant(NAN);
  }
  return segments_.nearestOn(segment, point);
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
