#include "side_colors.hpp"

#include <algorithm>

namespace vicc_glyphs {
namespace io_detail {
std::vector<ColorPoint> reduceColorRuns(const std::vector<ColorPoint>& samples, double segments) {
  std::vector<ColorPoint> points;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const bool same_as_previous = i > 0 && samples[i].rgb == samples[i - 1].rgb;
    const bool same_as_next = i + 1 < samples.size() && samples[i].rgb == samples[i + 1].rgb;
    if (!(same_as_previous && same_as_next)) points.push_back(samples[i]);
  }
  // A single colour holds along the whole curve.
  if (points.size() <= 2 && points.front().rgb == points.back().rgb) {
    return {ColorPoint{0.0, points.front().rgb}, ColorPoint{segments, points.front().rgb}};
  }
  return points;
}

std::vector<SideSample> sideSamples(const DiffusionCurve& curve, int per_segment,
                                    std::size_t max_samples,
                                    const std::function<double(double speed)>& offset) {
  const int segments = curve.segmentCount();
  const std::size_t wanted = static_cast<std::size_t>(segments) * std::max(per_segment, 1);
  const std::size_t count = std::min(wanted, std::max<std::size_t>(max_samples, 1));
  std::vector<SideSample> samples;
  for (std::size_t i = 0; i < count; ++i) {
    const double s = (static_cast<double>(i) + 0.5) * segments / static_cast<double>(count);
    const Point2 tangent = curve.derivativeAt(s);
    const double speed = tangent.norm();
    if (!(speed > 1e-12)) continue;
    const Point2 left_normal = Point2(tangent.y(), -tangent.x()) / speed;
    const double distance = offset(speed);
    const Point2 at = curve.pointAt(s);
    samples.push_back({s, at + distance * left_normal, at - distance * left_normal});
  }
  return samples;
}

void assignSideColors(DiffusionCurve& curve, const std::vector<SideSample>& samples,
                      const std::function<Color(const Point2&)>& color_at, const Color& fallback) {
  const double segments = curve.segmentCount();
  if (samples.empty()) {
    curve.left_colors = {{0.0, fallback}, {segments, fallback}};
    curve.right_colors = curve.left_colors;
    return;
  }
  std::vector<ColorPoint> left, right;
  for (const SideSample& sample : samples) {
    left.push_back({sample.s, color_at(sample.left)});
    right.push_back({sample.s, color_at(sample.right)});
  }
  curve.left_colors = reduceColorRuns(left, segments);
  curve.right_colors = reduceColorRuns(right, segments);
}

}  // namespace io_detail
}  // namespace vicc_glyphs
