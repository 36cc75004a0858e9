#include "vicc_glyphs/pacemod/nearest_curve_point.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vicc_glyphs {
namespace pacemod {

NearestCurvePoint::NearestCurvePoint(const std::vector<std::vector<Point2>>& polylines, int width,
                                     int height, double grid_scale, FeatureTransform method)
    : scale_(grid_scale), margin_(4) {
  if (width < 1 || height < 1 || !(grid_scale > 0.0) || !std::isfinite(grid_scale)) {
    throw std::invalid_argument("NearestCurvePoint: size and grid scale must be positive");
  }
  grid_ = cv::Size(static_cast<int>(std::ceil(width * scale_)) + 2 * margin_,
                   static_cast<int>(std::ceil(height * scale_)) + 2 * margin_);
  cv::Mat mask = cv::Mat::zeros(grid_, CV_8U);
  samples_.assign(mask.total(), Point2::Zero());
  std::vector<double> centre_distance(mask.total(), 1e300);
  // Samples at a quarter grid pixel mark every pixel a segment passes through; each pixel keeps
  // the sample nearest to its centre.
  const double step = 0.25 / scale_;
  auto mark = [&](const Point2& p) {
    const double gx = p.x() * scale_ + margin_, gy = p.y() * scale_ + margin_;
    const int ix = static_cast<int>(std::floor(gx)), iy = static_cast<int>(std::floor(gy));
    if (ix < 0 || iy < 0 || ix >= grid_.width || iy >= grid_.height) return;
    const int index = iy * grid_.width + ix;
    const double d = std::hypot(gx - ix - 0.5, gy - iy - 0.5);
    if (d < centre_distance[index]) {
      centre_distance[index] = d;
      samples_[index] = p;
      mask.at<unsigned char>(iy, ix) = 1;
    }
  };
  for (const std::vector<Point2>& line : polylines) {
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
      const int pieces =
          std::max(1, static_cast<int>(std::ceil((line[i + 1] - line[i]).norm() / step)));
      for (int k = 0; k < pieces; ++k)
        mark(line[i] + (line[i + 1] - line[i]) * (double(k) / pieces));
    }
    if (!line.empty()) mark(line.back());
  }
  if (cv::countNonZero(mask) == 0)
    throw std::invalid_argument("NearestCurvePoint: no curve points");
  feature_ = method == FeatureTransform::Maurer ? maurerFeatureTransform(mask)
                                                : openCvFeatureTransform(mask);
}

int NearestCurvePoint::featureAt(const Point2& query) const {
  // Clamp in floating point first: a far-away or non-finite query must not overflow an int.
  auto cell = [](double g, int size) {
    return static_cast<int>(std::isfinite(g) ? std::clamp(g, 0.0, size - 1.0) : 0.0);
  };
  const int ix = cell(query.x() * scale_ + margin_, grid_.width);
  const int iy = cell(query.y() * scale_ + margin_, grid_.height);
  return feature_[static_cast<std::size_t>(iy) * grid_.width + ix];
}

Point2 NearestCurvePoint::nearest(const Point2& query) const { return samples_[featureAt(query)]; }

}  // namespace pacemod
}  // namespace vicc_glyphs
