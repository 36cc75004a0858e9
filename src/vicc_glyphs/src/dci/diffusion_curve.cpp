#include "vicc_glyphs/dci/diffusion_curve.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <type_traits>
#include <utility>

namespace vicc_glyphs {
namespace {

// Splits s into (segment index, local parameter) for a curve with K segments.
std::pair<int, double> locate(double s, int segments) {
  const double clamped = std::clamp(s, 0.0, static_cast<double>(segments));
  const int k = std::min(static_cast<int>(std::floor(clamped)), segments - 1);
  return {k, clamped - k};
}

// Piecewise-linear interpolation of sorted points, constant beyond the ends; `value` picks the
// interpolated quantity (a colour or a blur sigma).
template <typename Points, typename Value>
auto interpolate(const Points& points, double s, Value value) -> decltype(value(points.front())) {
  using Result = decltype(value(points.front()));
  if (points.empty()) {
    if constexpr (std::is_arithmetic_v<Result>) {
      return Result{0};
    } else {
      return Result::Zero();
    }
  }
  if (s <= points.front().position) return value(points.front());
  if (s >= points.back().position) return value(points.back());
  const auto upper = std::upper_bound(points.begin(), points.end(), s,
                                      [](double v, const auto& p) { return v < p.position; });
  const auto lower = upper - 1;
  const double span = upper->position - lower->position;
  const double w = span > 0.0 ? (s - lower->position) / span : 0.0;
  return (1.0 - w) * value(*lower) + w * value(*upper);
}

bool finite(const Point2& p) { return std::isfinite(p.x()) && std::isfinite(p.y()); }

std::string checkColors(const std::vector<ColorPoint>& points, int segments, const char* side) {
  double previous = -1.0;
  for (const ColorPoint& c : points) {
    if (!std::isfinite(c.position) || c.position < 0.0 || c.position > segments) {
      return std::string(side) + " colour position out of [0, K]";
    }
    if (c.position < previous) return std::string(side) + " colour positions not sorted";
    previous = c.position;
    for (int i = 0; i < 3; ++i) {
      if (!std::isfinite(c.rgb[i]) || c.rgb[i] < 0.0 || c.rgb[i] > 1.0) {
        return std::string(side) + " colour outside [0, 1]";
      }
    }
  }
  return {};
}

}  // namespace

int DiffusionCurve::segmentCount() const {
  const int n = static_cast<int>(control_points.size());
  if (n < 4 || (n - 1) % 3 != 0) return 0;
  return (n - 1) / 3;
}

Point2 DiffusionCurve::pointAt(double s) const {
  const int segments = segmentCount();
  if (segments == 0) return control_points.empty() ? Point2::Zero() : control_points.front();
  const auto [k, t] = locate(s, segments);
  const Point2* b = &control_points[3 * k];
  const double u = 1.0 - t;
  return u * u * u * b[0] + 3.0 * u * u * t * b[1] + 3.0 * u * t * t * b[2] + t * t * t * b[3];
}

Point2 DiffusionCurve::derivativeAt(double s) const {
  const int segments = segmentCount();
  if (segments == 0) return Point2::Zero();
  const auto [k, t] = locate(s, segments);
  const Point2* b = &control_points[3 * k];
  const double u = 1.0 - t;
  return 3.0 * (u * u * (b[1] - b[0]) + 2.0 * u * t * (b[2] - b[1]) + t * t * (b[3] - b[2]));
}

Color interpolateColor(const std::vector<ColorPoint>& points, double s) {
  return interpolate(points, s, [](const ColorPoint& p) -> Color { return p.rgb; });
}

std::optional<Color> dominantColor(const std::vector<ColorPoint>& points) {
  if (points.empty()) return std::nullopt;
  std::vector<std::pair<Color, double>> weights;
  auto add = [&](const Color& rgb, double weight) {
    for (auto& [color, total] : weights) {
      if ((color - rgb).cwiseAbs().maxCoeff() <= kSameColorTolerance) {
        total += weight;
        return;
      }
    }
    weights.emplace_back(rgb, weight);
  };
  for (size_t i = 0; i + 1 < points.size(); ++i) {
    const double half = 0.5 * std::abs(points[i + 1].position - points[i].position);
    add(points[i].rgb, half);
    add(points[i + 1].rgb, half);
  }
  if (points.size() == 1) add(points.front().rgb, 1.0);
  return std::max_element(weights.begin(), weights.end(),
                          [](const auto& a, const auto& b) { return a.second < b.second; })
      ->first;
}

Color DiffusionCurve::leftColorAt(double s) const { return interpolateColor(left_colors, s); }
Color DiffusionCurve::rightColorAt(double s) const { return interpolateColor(right_colors, s); }

double DiffusionCurve::blurAt(double s) const {
  return interpolate(blur_points, s, [](const BlurPoint& p) { return p.sigma; });
}

std::string validate(const DiffusionCurveImage& image) {
  if (image.width <= 0 || image.height <= 0) return "image size must be positive";
  for (size_t i = 0; i < image.curves.size(); ++i) {
    const DiffusionCurve& curve = image.curves[i];
    std::ostringstream where;
    where << "curve " << i << ": ";
    const int segments = curve.segmentCount();
    if (segments == 0) {
      return where.str() + "needs 3K+1 control points (K >= 1), has " +
             std::to_string(curve.control_points.size());
    }
    for (const Point2& p : curve.control_points) {
      if (!finite(p)) return where.str() + "non-finite control point";
    }
    for (const auto& [points, side] :
         {std::pair{&curve.left_colors, "left"}, std::pair{&curve.right_colors, "right"}}) {
      const std::string problem = checkColors(*points, segments, side);
      if (!problem.empty()) return where.str() + problem;
    }
    for (const BlurPoint& b : curve.blur_points) {
      if (!std::isfinite(b.position) || !std::isfinite(b.sigma) || b.sigma < 0.0) {
        return where.str() + "invalid blur point";
      }
    }
  }
  return {};
}

DiffusionCurveImage scaledToWidth(const DiffusionCurveImage& image, int size) {
  DiffusionCurveImage scaled = image;
  if (image.width <= 0 || size <= 0) return scaled;
  const double factor = static_cast<double>(size) / image.width;
  scaled.width = size;
  scaled.height = std::max(1, static_cast<int>(std::lround(image.height * factor)));
  for (DiffusionCurve& curve : scaled.curves) {
    for (Point2& p : curve.control_points) p *= factor;
    for (BlurPoint& b : curve.blur_points) b.sigma *= factor;
  }
  return scaled;
}

}  // namespace vicc_glyphs
