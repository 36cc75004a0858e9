#include "wave_measurement.hpp"

#include <algorithm>
#include <cmath>

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

}  // namespace

ContourMeasure measureContour(const Polyline& original, const Polyline& modified,
                              const std::function<double(double arc_fraction)>& threshold) {
  std::vector<double> arcs{0.0};
  for (std::size_t i = 1; i < original.size(); ++i) {
    arcs.push_back(arcs.back() + (original[i] - original[i - 1]).norm());
  }
  const double total = arcs.back();
  for (double& arc : arcs) arc = total > 0.0 ? arc / total : 0.0;  // fractions of the length
  struct Sample {
    int sign;
    double magnitude;
    double arc;
    Point2 point;
  };
  std::vector<Sample> samples;
  for (std::size_t i = 0; i + 1 < modified.size(); ++i) {  // the last repeats the first
    const Nearest n = nearestOn(modified[i], original, arcs);
    const double arc = std::fmod(n.arc, 1.0);
    const int sign =
        n.distance <= threshold(arc) ? 0 : (insidePolygon(modified[i], original) ? -1 : 1);
    samples.push_back({sign, n.distance, arc, modified[i]});
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
      result.lobes.push_back({s.sign, 0.0, s.arc, s.arc, s.point});
    }
    Lobe& lobe = result.lobes.back();
    if (s.magnitude > lobe.extreme_px) {
      lobe.extreme_px = s.magnitude;
      lobe.extreme_point = s.point;
    }
    lobe.arc_end = s.arc;
  }
  for (const Lobe& lobe : result.lobes) (lobe.sign > 0 ? result.outward : result.inward)++;
  return result;
}

}  // namespace measure
}  // namespace pacemod
}  // namespace vicc_glyphs
