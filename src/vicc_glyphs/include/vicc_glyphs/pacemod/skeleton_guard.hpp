#pragma once
// Self-intersection prevention of thesis 6.2.4.1 (Fig. 6.14A): a knot point k translated by
// a along the unit direction n must stay inside the skeleton half-space of k, i.e. remain
// closer to k than to any other curve point p. Where it does not, the skeleton point
// s = k + a' n, equidistant to k and p, gives a' = 0.5 |p - k|^2 / <n, p - k>; the amplitude
// becomes a' - epsilon (free space between the curves) and the test is repeated, as the
// shorter translation may come closer to yet another curve point.

#include "vicc_glyphs/pacemod/nearest_curve_point.hpp"

namespace vicc_glyphs {
namespace pacemod {

/// The leg a' of the isosceles triangle with base p - k along n; +infinity when p is not in
/// front of k (<n, p - k> <= 0: p can never be closer than k along n).
double skeletonAmplitude(const Point2& knot, const Point2& direction, const Point2& other);

/// The same for a translation that takes the knot point away from its own contour by only
/// `growth` (in (0, 1]) per unit length, as along the bisector into an icon corner (the miter):
/// the smallest t > 0 with |k + t n - p| = growth * t, +infinity if there is none. growth = 1
/// is skeletonAmplitude.
double skeletonTranslation(const Point2& knot, const Point2& direction, const Point2& other,
                           double growth);

/// The guard's slack as a fraction of the amplitude. A whole grid pixel let offset points come
/// up to 12 % nearer to another curve point than their amplitude at 0.8 mm (MDI bench: an
/// inward lobe beside the brain's convex corner measured 7.04 px for 8.19); half the bench's
/// 10 % tolerance keeps them within it.
constexpr double kGuardSlack = 0.05;

struct GuardResult {
  double amplitude = 0.0;  ///< allowed amplitude, in [0, requested]
  bool reduced = false;
  int steps = 0;  ///< how many reductions were applied
};

class SkeletonGuard {
 public:
  /// `field`: nearest points on all curves of the unmodified icon; `epsilon`: the free space
  /// kept to the skeleton (image pixels). The field must outlive the guard.
  SkeletonGuard(const NearestCurvePoint& field, double epsilon);

  /// Largest allowed amplitude <= `requested` for translating `knot` along the unit
  /// `direction`. A curve point counts as closer only when it is closer by more than the
  /// field's grid pixel or kGuardSlack of the amplitude, whichever is less, so that k's own
  /// sampled neighbourhood does not trigger. With `growth` < 1 (a knot point on an icon corner
  /// moving along its miter) a translation t puts the point growth * t away from its contour:
  /// amplitudes are those distances (the translation is amplitude / growth), and a curve point
  /// closer than that distance is the one to avoid. A reduced amplitude below a tenth of an
  /// image pixel becomes 0.
  GuardResult limit(const Point2& knot, const Point2& direction, double requested,
                    double growth = 1.0) const;

  /// The free space kept to the skeleton (image pixels).
  double epsilon() const { return epsilon_; }

 private:
  const NearestCurvePoint& field_;
  double epsilon_;
};

}  // namespace pacemod
}  // namespace vicc_glyphs
