#include "vicc_glyphs/bspline/spline_diffusion_curve.hpp"

namespace vicc_glyphs {
namespace bspline {
namespace {

// Rewrites the `position` of every point with `map`; the maps are monotonic, so order holds.
template <typename Points, typename Map>
Points remapped(Points points, Map map) {
  for (auto& point : points) point.position = map(point.position);
  return points;
}

}  // namespace

SplineDiffusionCurve toSplineDiffusionCurve(const DiffusionCurve& curve,
                                            const BezierConversionOptions& options) {
  SplineFromBezier converted = bezierChainToBSpline(curve.control_points, options);
  const ChainParameterMap& map = converted.parameter_map;
  const auto toSpline = [&map](double s) { return map.toSplineParameter(s); };
  return SplineDiffusionCurve{std::move(converted.curve),
                              remapped(curve.left_colors, toSpline),
                              remapped(curve.right_colors, toSpline),
                              remapped(curve.blur_points, toSpline),
                              curve.left_emits,
                              curve.right_emits};
}

DiffusionCurve toDiffusionCurve(const SplineDiffusionCurve& curve) {
  BezierFromSpline chain = bsplineToBezierChain(curve.geometry);
  const ChainParameterMap& map = chain.parameter_map;
  const auto toCurve = [&map](double u) { return map.toCurveParameter(u); };
  DiffusionCurve result;
  result.control_points = std::move(chain.control_points);
  result.left_colors = remapped(curve.left_colors, toCurve);
  result.right_colors = remapped(curve.right_colors, toCurve);
  result.blur_points = remapped(curve.blur_points, toCurve);
  result.left_emits = curve.left_emits;
  result.right_emits = curve.right_emits;
  return result;
}

}  // namespace bspline
}  // namespace vicc_glyphs
