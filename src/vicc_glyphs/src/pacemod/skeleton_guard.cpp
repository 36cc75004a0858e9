#include "vicc_glyphs/pacemod/skeleton_guard.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vicc_glyphs {
namespace pacemod {

constexpr int kMaxGuardSteps = 64;

double skeletonAmplitude(const Point2& knot, const Point2& direction, const Point2& other) {
  const Point2 base = other - knot;
  const double along = direction.dot(base);
  if (!(along > 0.0)) return std::numeric_limits<double>::infinity();
  return 0.5 * base.squaredNorm() / along;
}

SkeletonGuard::SkeletonGuard(const NearestCurvePoint& field, double epsilon)
    : field_(field), epsilon_(epsilon) {}

GuardResult SkeletonGuard::limit(const Point2& knot, const Point2& direction,
                                 double requested) const {
  GuardResult result{std::max(requested, 0.0), false, 0};
  const double tolerance = field_.gridPixel();
  while (result.amplitude > 0.0 && result.steps < kMaxGuardSteps) {
    const Point2 moved = knot + result.amplitude * direction;
    const Point2 other = field_.nearest(moved);
    if ((moved - other).norm() >= result.amplitude - tolerance) break;
    const double skeleton = skeletonAmplitude(knot, direction, other);
    if (!std::isfinite(skeleton)) break;
    result.amplitude = std::clamp(skeleton - epsilon_, 0.0, result.amplitude);
    result.reduced = true;
    ++result.steps;
  }
  return result;
}

}  // namespace pacemod
}  // namespace vicc_glyphs
