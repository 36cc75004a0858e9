#include "wave_measurement.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

namespace vicc_glyphs {
namespace pacemod {
namespace measure {
namespace {

struct Nearest {
  double distance;
  double arc;
};

Nearest nearestOn(const Point2& p, const Polyline& line, const std::vector<double>& arcs) {
  Nearest best{1e300, 0.0};
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    const Point2 d = line[i + 1] - line[i];
    const double l2 = d.squaredNorm();
    const double t = l2 > 0 ? std::clamp((p - line[i]).dot(d) / l2, 0.0, 1.0) : 0.0;
    const double dist = (p - line[i] - t * d).norm();
    if (dist < best.distance) best = {dist, arcs[i] + t * (arcs[i + 1] - arcs[i])};
  }
  return best;
}

double cross(const Point2& a, const Point2& b) { return a.x() * b.y() - a.y() * b.x(); }

bool properlyCross(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 &&
         d4 != 0;
}

struct Segment {
  int line;
  int index;
};

// Segments bucketed on a uniform grid; `visit` gets every candidate pair once.
template <typename Visit>
void candidatePairs(const std::vector<Polyline>& lines, double cell, Visit visit) {
  std::unordered_map<long long, std::vector<Segment>> buckets;
  auto key = [](long long x, long long y) { return (x << 32) ^ (y & 0xffffffffLL); };
  for (int l = 0; l < static_cast<int>(lines.size()); ++l) {
    for (int i = 0; i + 1 < static_cast<int>(lines[l].size()); ++i) {
      const Point2 lo = lines[l][i].cwiseMin(lines[l][i + 1]) / cell;
      const Point2 hi = lines[l][i].cwiseMax(lines[l][i + 1]) / cell;
      for (long long x = std::floor(lo.x()); x <= std::floor(hi.x()); ++x) {
        for (long long y = std::floor(lo.y()); y <= std::floor(hi.y()); ++y) {
          buckets[key(x, y)].push_back({l, i});
        }
      }
    }
  }
  std::map<std::pair<long long, long long>, bool> seen;
  for (const auto& bucket : buckets) {
    const std::vector<Segment>& s = bucket.second;
    for (std::size_t a = 0; a < s.size(); ++a) {
      for (std::size_t b = a + 1; b < s.size(); ++b) {
        const long long ia = (static_cast<long long>(s[a].line) << 32) | s[a].index;
        const long long ib = (static_cast<long long>(s[b].line) << 32) | s[b].index;
        if (seen.emplace(std::minmax(ia, ib), true).second) visit(s[a], s[b]);
      }
    }
  }
}

int countCrossings(const std::vector<Polyline>& lines, bool same_line) {
  int count = 0;
  candidatePairs(lines, 8.0, [&](const Segment& a, const Segment& b) {
    if ((a.line == b.line) != same_line) return;
    const Polyline& la = lines[a.line];
    const Polyline& lb = lines[b.line];
    if (same_line) {
      const int n = static_cast<int>(la.size()) - 1;
      const int gap = std::abs(a.index - b.index);
      if (gap <= 1 || gap == n - 1) return;  // neighbours share an end point
    }
    count += properlyCross(la[a.index], la[a.index + 1], lb[b.index], lb[b.index + 1]);
  });
  return count;
}

}  // namespace

ContourMeasure measureContour(const Polyline& original, const Polyline& modified,
                              double threshold_px) {
  std::vector<double> arcs{0.0};
  for (std::size_t i = 1; i < original.size(); ++i) {
    arcs.push_back(arcs.back() + (original[i] - original[i - 1]).norm());
  }
  struct Sample {
    int sign;
    double magnitude;
    double arc;
  };
  std::vector<Sample> samples;
  for (std::size_t i = 0; i + 1 < modified.size(); ++i) {  // the last repeats the first
    const Nearest n = nearestOn(modified[i], original, arcs);
    const int sign =
        n.distance <= threshold_px ? 0 : (insidePolygon(modified[i], original) ? -1 : 1);
    samples.push_back({sign, n.distance, n.arc});
  }
  ContourMeasure result;
  // Start the cyclic scan at a sign change so that no lobe is split at the seam.
  std::vector<std::size_t> signed_samples;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (samples[i].sign != 0) signed_samples.push_back(i);
  }
  std::size_t offset = 0;
  for (std::size_t k = 0; k < signed_samples.size(); ++k) {
    const std::size_t previous =
        signed_samples[(k + signed_samples.size() - 1) % signed_samples.size()];
    if (samples[signed_samples[k]].sign != samples[previous].sign) {
      offset = signed_samples[k];
      break;
    }
  }
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const Sample& s = samples[(offset + k) % samples.size()];
    if (s.sign == 0) continue;
    if (result.lobes.empty() || result.lobes.back().sign != s.sign) {
      result.lobes.push_back({s.sign, 0.0, s.arc, s.arc});
    }
    Lobe& lobe = result.lobes.back();
    lobe.extreme_px = std::max(lobe.extreme_px, s.magnitude);
    lobe.arc_end = s.arc;
  }
  for (const Lobe& lobe : result.lobes) (lobe.sign > 0 ? result.outward : result.inward)++;
  return result;
}

int countSelfIntersections(const Polyline& line) { return countCrossings({line}, true); }

int countMutualIntersections(const std::vector<Polyline>& lines) {
  return countCrossings(lines, false);
}

}  // namespace measure
}  // namespace pacemod
}  // namespace vicc_glyphs
