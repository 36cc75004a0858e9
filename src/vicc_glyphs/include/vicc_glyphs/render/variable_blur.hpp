#pragma once
// Orzan's blur pass: a Gaussian blur whose sigma varies per pixel (the diffused blur field).
// Approximated by a stack of uniformly blurred copies at sigmas 0, 0.5, 1, 2, 4, ... and a
// per-pixel linear blend of the two copies whose sigmas bracket the pixel's sigma; copies with
// a large sigma are blurred at a reduced resolution.

#include <opencv2/core.hpp>

namespace vicc_glyphs {

/// `image`: CV_32FC3; `sigma`: CV_32FC1 of the same size, in pixels (negative treated as 0).
/// Returns a new CV_32FC3 image; replicates the border.
cv::Mat applyVariableBlur(const cv::Mat& image, const cv::Mat& sigma);

}  // namespace vicc_glyphs
