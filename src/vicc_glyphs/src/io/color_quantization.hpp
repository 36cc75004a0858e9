#pragma once
// Reduces an icon to a few flat colour regions: the exact palette when the image has few
// colours, otherwise k-means; clusters too small to be regions of their own (anti-aliasing
// fringes) are folded into the nearest remaining cluster.

#include <opencv2/core.hpp>
#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"

namespace vicc_glyphs {
namespace io_detail {

struct QuantizedImage {
  cv::Mat1i labels;              ///< cluster index per pixel
  std::vector<Color> palette;    ///< RGB in [0, 1] per cluster
  std::vector<int> pixel_count;  ///< pixels per cluster
};

/// `bgr` is 8-bit, 3 channels. `max_colors` >= 1; clusters with fewer than
/// `min_fraction` of all pixels are merged away (the largest one always survives).
QuantizedImage quantizeColors(const cv::Mat3b& bgr, int max_colors, double min_fraction);

}  // namespace io_detail
}  // namespace vicc_glyphs
