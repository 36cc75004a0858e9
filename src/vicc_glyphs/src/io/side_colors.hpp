#pragma once
// Colour constraints for a curve from a colour lookup: the lookup is asked a small distance to
// the left and to the right of the curve at sample parameters, and equal neighbouring samples
// are merged so a uniformly coloured side gets just its two end points.

#include <functional>
#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"

namespace vicc_glyphs {
namespace io_detail {

/// A place beside a curve: parameter s and the points at the left and right offsets.
struct SideSample {
  double s = 0.0;
  Point2 left = Point2::Zero();
  Point2 right = Point2::Zero();
};

/// Samples at `per_segment` evenly spaced parameters inside each segment (at most
/// `max_samples` in all), `offset` along the unit left normal; places where the curve has no
/// tangent are skipped. `offset` may depend on the local speed |dB/ds|.
std::vector<SideSample> sideSamples(const DiffusionCurve& curve, int per_segment,
                                    std::size_t max_samples,
                                    const std::function<double(double speed)>& offset);

/// Colour points with runs of equal colours reduced to their ends; a single colour becomes the
/// two points 0 and `segments` (the whole curve). `samples` must not be empty.
std::vector<ColorPoint> reduceColorRuns(const std::vector<ColorPoint>& samples, double segments);

/// Sets left_colors / right_colors from `color_at` at the samples (runs of equal colours are
/// reduced to their ends; a uniform side spans [0, K] with two points). With no samples both
/// sides get `fallback`.
void assignSideColors(DiffusionCurve& curve, const std::vector<SideSample>& samples,
                      const std::function<Color(const Point2&)>& color_at, const Color& fallback);

}  // namespace io_detail
}  // namespace vicc_glyphs
