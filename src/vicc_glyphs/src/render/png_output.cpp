#include "vicc_glyphs/render/png_output.hpp"

#include <stdexcept>

#include "vicc_glyphs/io/png_codec.hpp"

namespace vicc_glyphs {

cv::Mat toRgb8(const cv::Mat& rgb) {
  if (rgb.type() != CV_32FC3) throw std::invalid_argument("toRgb8: expects CV_32FC3");
  cv::Mat bytes;
  rgb.convertTo(bytes, CV_8UC3, 255.0);  // rounds and saturates
  return bytes;
}

void writePng(const cv::Mat& rgb, const std::string& path) {
  if (rgb.empty()) throw std::runtime_error("cannot write an empty image to " + path);
  writePng8(toRgb8(rgb), ChannelOrder::kRgb, path);
}

}  // namespace vicc_glyphs
