#pragma once
// Distance-field isolines of a closed contour (thesis 6.2.3.3, "Shrinking and Inflating of Icon
// Parts" and diffusion barriers): the region enclosed by the contour is rasterised finely, its
// signed distance field computed (OpenCV distance transforms of the region and of its
// complement), the isoline at the requested offset traced and fitted by a closed cubic B-spline
// (least squares, then Fowler-Bartels pins the closing point and equal end tangents), which
// becomes a Bezier chain.

#include <opencv2/core.hpp>
#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"
#include "vicc_glyphs/pacemod/polyline.hpp"

namespace vicc_glyphs {
namespace pacemod {

/// The isoline at signed distance `offset` (pixels; > 0 outside = inflated, < 0 inside =
/// shrunk) of the region enclosed by the closed `contour`, as a closed polyline with the same
/// orientation as `contour`; where the region splits, the largest part; empty when nothing is
/// left. `grid_scale` grid pixels per image pixel (the grid is capped at 2048 pixels a side).
Polyline offsetIsoline(const Polyline& contour, double offset, double grid_scale = 4.0);

/// offsetIsoline of the region less every point within `clearance` pixels of the regions of
/// `obstacles` (closed polylines), so that an inflated part stops short of its neighbours;
/// `limited` (if given) says whether that took anything away.
Polyline offsetIsolineAvoiding(const Polyline& contour, double offset,
                               const std::vector<Polyline>& obstacles, double clearance,
                               double grid_scale = 4.0, bool* limited = nullptr);

namespace detail {
/// The raster the isolines are traced on: image position of its corner, grid pixels per image
/// pixel, size.
struct IsolineGrid {
  Point2 origin = Point2::Zero();
  double scale = 1.0;
  cv::Size size;
};
}  // namespace detail

/// The distance field inside the region of a closed contour, for isolines at several offsets
/// inside it: one distance transform for all of them (the gradient glyph's band and centre
/// region are both insets of one contour).
class InsideDistance {
 public:
  explicit InsideDistance(const Polyline& contour, double grid_scale = 4.0);
  /// offsetIsoline(contour, offset, grid_scale) for an offset <= 0 (pixels).
  Polyline isoline(double offset) const;

 private:
  Polyline contour_;
  detail::IsolineGrid grid_;
  cv::Mat field_;  ///< grid pixels, negative inside (0 outside)
};

/// A closed polyline (first == last point) as a closed Bezier chain (3K+1 points) of a
/// least-squares cubic B-spline with knots about `knot_spacing` pixels apart. Throws
/// std::invalid_argument for fewer than 4 distinct points.
std::vector<Point2> closedBezierFit(const Polyline& line, double knot_spacing = 6.0);

}  // namespace pacemod
}  // namespace vicc_glyphs
