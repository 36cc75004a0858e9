#include "vicc_glyphs/render/variable_blur.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <vector>

namespace vicc_glyphs {

namespace {

// Gaussian blur; large sigmas are applied at a reduced resolution (area downsampling, blur,
// bilinear upsampling), which keeps the cost independent of sigma. The downsampling box of
// width f has standard deviation about f / sqrt(12) and the bilinear upsampling adds about
// as much again; the blur at the reduced resolution supplies the rest of sigma.
cv::Mat gaussianBlur(const cv::Mat& image, double sigma) {
  int factor = 1;
  while (sigma >= 4.0 * factor && std::min(image.cols, image.rows) >= 16 * factor) factor *= 2;
  cv::Mat blurred;
  if (factor == 1) {
    cv::GaussianBlur(image, blurred, cv::Size(0, 0), sigma, sigma, cv::BORDER_REPLICATE);
    return blurred;
  }
  cv::Mat small;
  cv::resize(image, small,
             cv::Size((image.cols + factor - 1) / factor, (image.rows + factor - 1) / factor), 0, 0,
             cv::INTER_AREA);
  const double resampling_variance = factor * factor / 6.0;
  const double remaining = std::sqrt(std::max(sigma * sigma - resampling_variance, 0.25));
  cv::GaussianBlur(small, small, cv::Size(0, 0), remaining / factor, remaining / factor,
                   cv::BORDER_REPLICATE);
  cv::resize(small, blurred, image.size(), 0, 0, cv::INTER_LINEAR);
  return blurred;
}

}  // namespace

cv::Mat applyVariableBlur(const cv::Mat& image, const cv::Mat& sigma) {
  if (image.type() != CV_32FC3 || sigma.type() != CV_32FC1 || image.size() != sigma.size()) {
    throw std::invalid_argument("applyVariableBlur: needs CV_32FC3 and CV_32FC1 of one size");
  }
  double max_sigma = 0.0;
  cv::minMaxLoc(sigma, nullptr, &max_sigma);
  if (image.empty() || max_sigma <= 0.0) return image.clone();

  // Octave-spaced sigmas: the blend error stays small because blurs at neighbouring sigmas of
  // a geometric ladder differ little relative to their size.
  std::vector<double> sigmas{0.0, 0.5};
  while (sigmas.back() < max_sigma) sigmas.push_back(sigmas.back() * 2.0);
  std::vector<cv::Mat> stack{image};
  for (size_t k = 1; k < sigmas.size(); ++k) stack.push_back(gaussianBlur(image, sigmas[k]));

  cv::Mat result(image.size(), CV_32FC3);
  for (int y = 0; y < image.rows; ++y) {
    const float* s = sigma.ptr<float>(y);
    cv::Vec3f* out = result.ptr<cv::Vec3f>(y);
    for (int x = 0; x < image.cols; ++x) {
      const double value = std::clamp(static_cast<double>(s[x]), 0.0, sigmas.back());
      size_t upper = 1;
      while (upper + 1 < sigmas.size() && sigmas[upper] < value) ++upper;
      const double w = (value - sigmas[upper - 1]) / (sigmas[upper] - sigmas[upper - 1]);
      const float wf = static_cast<float>(std::clamp(w, 0.0, 1.0));
      out[x] = (1.0f - wf) * stack[upper - 1].at<cv::Vec3f>(y, x) +
               wf * stack[upper].at<cv::Vec3f>(y, x);
    }
  }
  return result;
}

}  // namespace vicc_glyphs
