#include "vicc_glyphs/pacemod/skeleton_guard.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace vicc_glyphs {
namespace pacemod {

constexpr int kMaxGuardSteps = 64;
// A reduced amplitude below this (image pixels) becomes 0: a wave that small cannot be seen, and
// a knot point translated by it keeps the contour from staying the original there (the
// re-fit between it and a flat neighbour beside an icon corner left blips of 0.2-0.5 px).
constexpr double kNegligibleAmplitude = 0.1;

double skeletonAmplitude(const Point2& knot, const Point2& direction, const Point2& other) {
  const Point2 base = other - knot;
  const double along = direction.dot(base);
  if (!(along > 0.0)) return std::numeric_limits<double>::infinity();
  return 0.5 * base.squaredNorm() / along;
}

double skeletonTranslation(const Point2& knot, const Point2& direction, const Point2& other,
                           double growth) {
  if (growth >= 1.0) return skeletonAmplitude(knot, direction, other);
  // |b - t n|^2 = g^2 t^2 with b = p - k: (1 - g^2) t^2 - 2 <n, b> t + |b|^2 = 0.
  const Point2 base = other - knot;
  const double along = direction.dot(base);
  const double a = 1.0 - growth * growth, c = base.squaredNorm();
  const double discriminant = along * along - a * c;
  if (!(along > 0.0) || discriminant < 0.0) return std::numeric_limits<double>::infinity();
  return (along - std::sqrt(discriminant)) / a;
}

SkeletonGuard::SkeletonGuard(const NearestCurvePoint& field, double epsilon)
    : field_(field), epsilon_(epsilon) {}

GuardResult SkeletonGuard::limit(const Point2& knot, const Point2& direction, double requested,
                                 double growth) const {
  GuardResult result{std::max(requested, 0.0), false, 0};
  while (result.amplitude > 0.0 && result.steps < kMaxGuardSteps) {
    const double tolerance = std::min(field_.gridPixel(), kGuardSlack * result.amplitude);
    const Point2 moved = knot + (result.amplitude / growth) * direction;
    const std::optional<Point2> other = field_.nearestWithin(moved, result.amplitude - tolerance);
    if (!other) break;
    const double skeleton = growth * skeletonTranslation(knot, direction, *other, growth);
    if (!std::isfinite(skeleton)) break;
    result.amplitude = std::clamp(skeleton - epsilon_, 0.0, result.amplitude);
    if (result.amplitude < kNegligibleAmplitude) result.amplitude = 0.0;
    result.reduced = true;
    ++result.steps;
  }
  return result;
}

}  // namespace pacemod
}  // namespace vicc_glyphs
