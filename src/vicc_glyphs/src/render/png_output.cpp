#include "vicc_glyphs/render/png_output.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace vicc_glyphs {

cv::Mat toRgb8(const cv::Mat& rgb) {
  if (rgb.type() != CV_32FC3) throw std::invalid_argument("toRgb8: expects CV_32FC3");
  cv::Mat bytes;
  rgb.convertTo(bytes, CV_8UC3, 255.0);  // rounds and saturates
  return bytes;
}

void writePng(const cv::Mat& rgb, const std::string& path) {
  if (rgb.empty()) throw std::runtime_error("cannot write an empty image to " + path);
  cv::Mat bgr;
  cv::cvtColor(toRgb8(rgb), bgr, cv::COLOR_RGB2BGR);
  bool written = false;
  try {
    written = cv::imwrite(path, bgr);
  } catch (const cv::Exception& e) {
    throw std::runtime_error("cannot write " + path + ": " + e.what());
  }
  if (!written) throw std::runtime_error("cannot write " + path);
}

}  // namespace vicc_glyphs
