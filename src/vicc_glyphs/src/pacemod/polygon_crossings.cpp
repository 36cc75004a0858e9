#include "vicc_glyphs/pacemod/polygon_crossings.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

namespace vicc_glyphs {
namespace pacemod {
namespace {

double cross(const Point2& a, const Point2& b) { return a.x() * b.y() - a.y() * b.x(); }

bool properlyCross(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  return d1 * d2 < 0.0 && d3 * d4 < 0.0;
}

// Neighbouring segments of one polyline share a point; so do the first and last of a closed one.
bool adjacent(int segments, bool closed, int i, int j) {
  const int gap = std::abs(i - j);
  return gap <= 1 || (closed && gap == segments - 1);
}

struct CellEntry {
  long long cell;
  SegmentRef segment;
  Point2 lo, hi;  ///< the segment's bounding box
};

long long cellKey(long long x, long long y) { return (x << 32) ^ (y & 0xffffffffLL); }

// Every segment once per grid cell its bounding box touches, sorted by cell.
std::vector<CellEntry> bucketSegments(const std::vector<Polyline>& lines, double cell) {
  std::vector<CellEntry> entries;
  for (int l = 0; l < static_cast<int>(lines.size()); ++l) {
    for (int i = 0; i + 1 < static_cast<int>(lines[l].size()); ++i) {
      const Point2 box_lo = lines[l][i].cwiseMin(lines[l][i + 1]);
      const Point2 box_hi = lines[l][i].cwiseMax(lines[l][i + 1]);
      const Point2 lo = box_lo / cell, hi = box_hi / cell;
      if (!lo.allFinite() || !hi.allFinite()) continue;
      for (long long x = std::floor(lo.x()); x <= std::floor(hi.x()); ++x) {
        for (long long y = std::floor(lo.y()); y <= std::floor(hi.y()); ++y) {
          entries.push_back({cellKey(x, y), {l, i}, box_lo, box_hi});
        }
      }
    }
  }
  std::sort(entries.begin(), entries.end(),
            [](const CellEntry& a, const CellEntry& b) { return a.cell < b.cell; });
  return entries;
}

// A crossing pair shares every cell that both bounding boxes touch; it is reported only in
// the cell of its crossing point (clamped into both boxes against round-off), so exactly once.
bool ownedByCell(const Point2& a0, const Point2& a1, const Point2& b0, const Point2& b1,
                 double cell, long long key) {
  const Point2 da = a1 - a0, db = b1 - b0;
  const double t = cross(b0 - a0, db) / cross(da, db);
  const Point2 lo = a0.cwiseMin(a1).cwiseMax(b0.cwiseMin(b1));
  const Point2 hi = a0.cwiseMax(a1).cwiseMin(b0.cwiseMax(b1));
  const Point2 point = (a0 + t * da).cwiseMax(lo).cwiseMin(hi) / cell;
  return cellKey(std::floor(point.x()), std::floor(point.y())) == key;
}

}  // namespace

std::vector<Crossing> findCrossings(const std::vector<Polyline>& lines, double cell) {
  std::vector<char> closed(lines.size());
  for (std::size_t l = 0; l < lines.size(); ++l) {
    closed[l] = lines[l].size() > 1 && (lines[l].front() - lines[l].back()).norm() < 1e-9;
  }
  const std::vector<CellEntry> entries = bucketSegments(lines, cell);
  std::vector<Crossing> crossings;
  for (std::size_t begin = 0, end = 0; begin < entries.size(); begin = end) {
    while (end < entries.size() && entries[end].cell == entries[begin].cell) ++end;
    for (std::size_t a = begin; a < end; ++a) {
      for (std::size_t b = a + 1; b < end; ++b) {
        // Densely sampled curves put many short segments into a cell: most pairs are apart.
        if ((entries[a].lo.array() > entries[b].hi.array()).any() ||
            (entries[b].lo.array() > entries[a].hi.array()).any()) {
          continue;
        }
        // Canonical order, so that the crossing point is computed the same in every cell.
        SegmentRef p = entries[a].segment, q = entries[b].segment;
        if (std::tie(q.line, q.segment) < std::tie(p.line, p.segment)) std::swap(p, q);
        const int segments = static_cast<int>(lines[p.line].size()) - 1;
        if (p.line == q.line && adjacent(segments, closed[p.line], p.segment, q.segment)) continue;
        const Point2& a0 = lines[p.line][p.segment];
        const Point2& a1 = lines[p.line][p.segment + 1];
        const Point2& b0 = lines[q.line][q.segment];
        const Point2& b1 = lines[q.line][q.segment + 1];
        if (!properlyCross(a0, a1, b0, b1)) continue;
        if (ownedByCell(a0, a1, b0, b1, cell, entries[begin].cell)) crossings.push_back({p, q});
      }
    }
  }
  // A deterministic order that does not depend on the bucketing.
  std::sort(crossings.begin(), crossings.end(), [](const Crossing& x, const Crossing& y) {
    return std::tie(x.a.line, x.a.segment, x.b.line, x.b.segment) <
           std::tie(y.a.line, y.a.segment, y.b.line, y.b.segment);
  });
  return crossings;
}

}  // namespace pacemod
}  // namespace vicc_glyphs
