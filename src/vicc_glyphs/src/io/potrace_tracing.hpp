#pragma once
// Boundary tracing of a binary mask with potrace: each traced path becomes a closed chain of
// cubic Beziers in image coordinates (x right, y down, pixel (i, j) covers [i, i+1) x [j, j+1)).

#include <opencv2/core.hpp>
#include <vector>

#include "svg_geometry.hpp"

namespace vicc_glyphs {
namespace io_detail {

struct TraceOptions {
  int min_region_area = 8;        ///< potrace turdsize
  double corner_threshold = 1.0;  ///< potrace alphamax
};

/// Traces the non-zero pixels of `mask`. Throws std::runtime_error if potrace fails and
/// std::length_error when `budget` runs out.
std::vector<Contour> traceMask(const cv::Mat1b& mask, const TraceOptions& options,
                               PointBudget& budget);

}  // namespace io_detail
}  // namespace vicc_glyphs
