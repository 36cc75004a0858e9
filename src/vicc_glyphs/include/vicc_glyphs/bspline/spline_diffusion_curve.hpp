#pragma once
// A diffusion curve whose geometry is a B-spline (the PACEMOD representation of thesis
// 6.2.3.2): colour and blur points sit at spline parameters u instead of the chain parameter s.

#include <vector>

#include "vicc_glyphs/bspline/bezier_conversion.hpp"
#include "vicc_glyphs/bspline/bspline_curve.hpp"
#include "vicc_glyphs/dci/diffusion_curve.hpp"

namespace vicc_glyphs {
namespace bspline {

struct SplineDiffusionCurve {
  BSplineCurve geometry;
  std::vector<ColorPoint> left_colors;   ///< position = spline parameter u, sorted
  std::vector<ColorPoint> right_colors;  ///< position = spline parameter u, sorted
  std::vector<BlurPoint> blur_points;    ///< position = spline parameter u, sorted
  bool left_emits = true;
  bool right_emits = true;
};

/// Pre-processing: geometry by bezierChainToBSpline, colour and blur positions mapped from s to
/// u. Throws std::invalid_argument for invalid geometry (see bezierChainToBSpline).
SplineDiffusionCurve toSplineDiffusionCurve(const DiffusionCurve& curve,
                                            const BezierConversionOptions& options = {});

/// Post-processing: geometry by bsplineToBezierChain, positions mapped from u to the new
/// chain's s (one Bezier segment per knot span of the spline).
DiffusionCurve toDiffusionCurve(const SplineDiffusionCurve& curve);

}  // namespace bspline
}  // namespace vicc_glyphs
