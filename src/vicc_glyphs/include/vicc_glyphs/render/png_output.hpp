#pragma once
// 8-bit output of rendered images. Colour values are written as they are (value * 255,
// rounded, clamped): the formats this package reads store 8-bit colours / 255, so a colour
// read from a file comes back out unchanged.

#include <opencv2/core.hpp>
#include <string>

namespace vicc_glyphs {

/// CV_32FC3 RGB in [0, 1] -> CV_8UC3 RGB.
cv::Mat toRgb8(const cv::Mat& rgb);

/// Writes a CV_32FC3 RGB image as PNG. Throws std::runtime_error if it cannot be written.
void writePng(const cv::Mat& rgb, const std::string& path);

}  // namespace vicc_glyphs
