#include "color_quantization.hpp"

#include <algorithm>
#include <map>
#include <opencv2/core.hpp>

namespace vicc_glyphs {
namespace io_detail {
namespace {

Color toRgb(const cv::Vec3f& bgr) { return Color(bgr[2], bgr[1], bgr[0]) / 255.0; }

// The exact colours, or an empty vector once there are more than `limit`.
std::vector<cv::Vec3b> distinctColors(const cv::Mat3b& bgr, int limit) {
  std::map<int, cv::Vec3b> seen;
  for (auto it = bgr.begin(); it != bgr.end(); ++it) {
    const cv::Vec3b c = *it;
    seen.emplace((c[0] << 16) | (c[1] << 8) | c[2], c);
    if (static_cast<int>(seen.size()) > limit) return {};
  }
  std::vector<cv::Vec3b> colors;
  for (const auto& entry : seen) colors.push_back(entry.second);
  return colors;
}

int nearest(const cv::Vec3f& color, const std::vector<cv::Vec3f>& centres,
            const std::vector<bool>& alive) {
  int best = -1;
  double best_distance = 0.0;
  for (std::size_t i = 0; i < centres.size(); ++i) {
    if (!alive[i]) continue;
    const double distance = cv::norm(color - centres[i]);
    if (best < 0 || distance < best_distance) {
      best = static_cast<int>(i);
      best_distance = distance;
    }
  }
  return best;
}

}  // namespace

QuantizedImage quantizeColors(const cv::Mat3b& bgr, int max_colors, double min_fraction) {
  max_colors = std::max(max_colors, 1);
  QuantizedImage result;
  result.labels = cv::Mat1i(bgr.size(), 0);
  std::vector<cv::Vec3f> centres;
  const std::vector<cv::Vec3b> exact = distinctColors(bgr, max_colors);
  if (!exact.empty()) {
    for (const cv::Vec3b& c : exact) centres.emplace_back(c[0], c[1], c[2]);
    for (int y = 0; y < bgr.rows; ++y) {
      for (int x = 0; x < bgr.cols; ++x) {
        const auto match = std::find(exact.begin(), exact.end(), bgr(y, x));
        result.labels(y, x) = static_cast<int>(match - exact.begin());
      }
    }
  } else {
    cv::Mat samples;
    bgr.reshape(1, static_cast<int>(bgr.total())).convertTo(samples, CV_32F);
    cv::Mat labels, kmeans_centres;
    cv::theRNG().state = 0x5eed;  // deterministic imports
    cv::kmeans(samples, max_colors, labels,
               cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 20, 0.5), 3,
               cv::KMEANS_PP_CENTERS, kmeans_centres);
    for (int i = 0; i < kmeans_centres.rows; ++i) {
      centres.emplace_back(kmeans_centres.at<float>(i, 0), kmeans_centres.at<float>(i, 1),
                           kmeans_centres.at<float>(i, 2));
    }
    labels.reshape(1, bgr.rows).copyTo(result.labels);
  }

  // Fold small clusters into the nearest surviving one, pixel by pixel.
  std::vector<int> counts(centres.size(), 0);
  for (auto it = result.labels.begin(); it != result.labels.end(); ++it) ++counts[*it];
  const int largest =
      static_cast<int>(std::max_element(counts.begin(), counts.end()) - counts.begin());
  std::vector<bool> alive(centres.size());
  for (std::size_t i = 0; i < centres.size(); ++i) {
    alive[i] = static_cast<int>(i) == largest || counts[i] >= min_fraction * bgr.total();
  }
  for (int y = 0; y < bgr.rows; ++y) {
    for (int x = 0; x < bgr.cols; ++x) {
      int& label = result.labels(y, x);
      if (!alive[label]) {
        const cv::Vec3b c = bgr(y, x);
        label = nearest(cv::Vec3f(c[0], c[1], c[2]), centres, alive);
      }
    }
  }
  // Renumber the survivors densely.
  std::vector<int> renumbered(centres.size(), -1);
  for (std::size_t i = 0; i < centres.size(); ++i) {
    if (!alive[i]) continue;
    renumbered[i] = static_cast<int>(result.palette.size());
    result.palette.push_back(toRgb(centres[i]));
    result.pixel_count.push_back(0);
  }
  for (auto it = result.labels.begin(); it != result.labels.end(); ++it) {
    *it = renumbered[*it];
    ++result.pixel_count[*it];
  }
  return result;
}

}  // namespace io_detail
}  // namespace vicc_glyphs
