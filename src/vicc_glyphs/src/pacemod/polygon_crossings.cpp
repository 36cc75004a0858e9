#include "vicc_glyphs/pacemod/polygon_crossings.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <unordered_map>
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
bool adjacent(const Polyline& line, int i, int j) {
  const int last = static_cast<int>(line.size()) - 2;
  const int gap = std::abs(i - j);
  const bool closed = (line.front() - line.back()).norm() < 1e-9;
  return gap <= 1 || (closed && gap == last);
}

long long cellKey(long long x, long long y) { return (x << 32) ^ (y & 0xffffffffLL); }

}  // namespace

std::vector<Crossing> findCrossings(const std::vector<Polyline>& lines, double cell) {
  std::unordered_map<long long, std::vector<SegmentRef>> buckets;
  for (int l = 0; l < static_cast<int>(lines.size()); ++l) {
    for (int i = 0; i + 1 < static_cast<int>(lines[l].size()); ++i) {
      const Point2 lo = lines[l][i].cwiseMin(lines[l][i + 1]) / cell;
      const Point2 hi = lines[l][i].cwiseMax(lines[l][i + 1]) / cell;
      if (!lo.allFinite() || !hi.allFinite()) continue;
      for (long long x = std::floor(lo.x()); x <= std::floor(hi.x()); ++x) {
        for (long long y = std::floor(lo.y()); y <= std::floor(hi.y()); ++y) {
          buckets[cellKey(x, y)].push_back({l, i});
        }
      }
    }
  }
  std::set<std::pair<std::pair<int, int>, std::pair<int, int>>> seen;
  std::vector<Crossing> crossings;
  for (const auto& bucket : buckets) {
    const std::vector<SegmentRef>& s = bucket.second;
    for (std::size_t a = 0; a < s.size(); ++a) {
      for (std::size_t b = a + 1; b < s.size(); ++b) {
        const SegmentRef& p = s[a];
        const SegmentRef& q = s[b];
        if (p.line == q.line && adjacent(lines[p.line], p.segment, q.segment)) continue;
        const Point2& a0 = lines[p.line][p.segment];
        const Point2& a1 = lines[p.line][p.segment + 1];
        const Point2& b0 = lines[q.line][q.segment];
        const Point2& b1 = lines[q.line][q.segment + 1];
        if (!properlyCross(a0, a1, b0, b1)) continue;
        // A crossing pair shares several buckets; report it once.
        const std::pair<int, int> ka{p.line, p.segment}, kb{q.line, q.segment};
        if (seen.insert({std::min(ka, kb), std::max(ka, kb)}).second) {
          crossings.push_back({p, q});
        }
      }
    }
  }
  return crossings;
}

}  // namespace pacemod
}  // namespace vicc_glyphs
