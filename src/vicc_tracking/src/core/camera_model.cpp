#include "vicc_tracking/camera_model.hpp"

#include <cmath>
#include <stdexcept>

#include <opencv2/calib3d.hpp>

namespace vicc_tracking {

DistortionModel distortionModelFromString(const std::string& name) {
  if (name.empty() || name == "none") return DistortionModel::kNone;
  if (name == "plumb_bob") return DistortionModel::kPlumbBob;
  if (name == "equidistant") return DistortionModel::kEquidistant;
  throw std::invalid_argument("unsupported distortion model '" + name +
                              "' (supported: plumb_bob, equidistant, none)");
}

std::string toString(DistortionModel model) {
  switch (model) {
    case DistortionModel::kPlumbBob:
      return "plumb_bob";
    case DistortionModel::kEquidistant:
      return "equidistant";
    case DistortionModel::kNone:
      break;
  }
  return "none";
}

void CameraModel::validate() const {
  if (width <= 0 || height <= 0) {
    throw std::invalid_argument("camera size must be positive, got " + std::to_string(width) +
                                "x" + std::to_string(height));
  }
  auto finite_positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!finite_positive(fx) || !finite_positive(fy)) {
    throw std::invalid_argument("camera focal lengths (fx = " + std::to_string(fx) +
                                ", fy = " + std::to_string(fy) + ") must be finite and positive");
  }
  if (!std::isfinite(cx) || !std::isfinite(cy)) {
    throw std::invalid_argument("camera principal point must be finite");
  }
  for (double d : distortion) {
    if (!std::isfinite(d)) throw std::invalid_argument("distortion coefficient is not finite");
  }
  if (model == DistortionModel::kPlumbBob && !distortion.empty() && distortion.size() != 5 &&
      distortion.size() != 4) {
    throw std::invalid_argument("plumb_bob needs 4 or 5 coefficients, got " +
                                std::to_string(distortion.size()));
  }
  if (model == DistortionModel::kEquidistant && !distortion.empty() && distortion.size() != 4) {
    throw std::invalid_argument("equidistant needs 4 coefficients, got " +
                                std::to_string(distortion.size()));
  }
}

bool CameraModel::hasDistortion() const {
  if (model == DistortionModel::kNone) return false;
  for (double d : distortion) {
    if (d != 0.0) return true;
  }
  return false;
}

cv::Matx33d CameraModel::intrinsicMatrix() const {
  return cv::Matx33d(fx, 0.0, cx, 0.0, fy, cy, 0.0, 0.0, 1.0);
}

cv::Mat CameraModel::distortionCoefficients() const {
  if (!hasDistortion()) return cv::Mat();
  cv::Mat coefficients(1, static_cast<int>(distortion.size()), CV_64F);
  for (size_t i = 0; i < distortion.size(); ++i) coefficients.at<double>(0, i) = distortion[i];
  return coefficients;
}

Eigen::Vector2d CameraModel::project(const Eigen::Vector3d& point_camera) const {
  const double x = point_camera.x() / point_camera.z();
  const double y = point_camera.y() / point_camera.z();
  double xd = x;
  double yd = y;
  if (hasDistortion() && model == DistortionModel::kPlumbBob) {
    const double k1 = distortion[0], k2 = distortion[1], p1 = distortion[2], p2 = distortion[3];
    const double k3 = distortion.size() > 4 ? distortion[4] : 0.0;
    const double r2 = x * x + y * y;
    const double radial = 1.0 + r2 * (k1 + r2 * (k2 + r2 * k3));
    xd = x * radial + 2.0 * p1 * x * y + p2 * (r2 + 2.0 * x * x);
    yd = y * radial + p1 * (r2 + 2.0 * y * y) + 2.0 * p2 * x * y;
  } else if (hasDistortion() && model == DistortionModel::kEquidistant) {
    const double r = std::sqrt(x * x + y * y);
    if (r > 1e-12) {
      const double theta = std::atan(r);
      const double t2 = theta * theta;
      const double theta_d =
          theta *
          (1.0 + t2 * (distortion[0] + t2 * (distortion[1] + t2 * (distortion[2] + t2 * distortion[3]))));
      xd = x * theta_d / r;
      yd = y * theta_d / r;
    }
  }
  return {fx * xd + cx, fy * yd + cy};
}

Eigen::Vector2d CameraModel::unprojectToNormalized(const Eigen::Vector2d& distorted_pixel) const {
  std::vector<cv::Point2d> in{{distorted_pixel.x(), distorted_pixel.y()}};
  std::vector<cv::Point2d> out;
  if (!hasDistortion()) {
    return {(distorted_pixel.x() - cx) / fx, (distorted_pixel.y() - cy) / fy};
  }
  const cv::TermCriteria criteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 50, 1e-12);
  if (model == DistortionModel::kEquidistant) {
    cv::fisheye::undistortPoints(in, out, intrinsicMatrix(), distortionCoefficients(), cv::noArray(),
                                 cv::noArray(), criteria);
  } else {
    cv::undistortPoints(in, out, intrinsicMatrix(), distortionCoefficients(), cv::noArray(),
                        cv::noArray(), criteria);
  }
  return {out[0].x, out[0].y};
}

std::vector<Eigen::Vector2d> CameraModel::normalizedRaysForAllPixels() const {
  std::vector<cv::Point2d> pixels;
  pixels.reserve(static_cast<size_t>(width) * height);
  for (int v = 0; v < height; ++v) {
    for (int u = 0; u < width; ++u) pixels.emplace_back(u, v);
  }
  std::vector<Eigen::Vector2d> rays;
  rays.reserve(pixels.size());
  if (!hasDistortion()) {
    for (const auto& p : pixels) rays.emplace_back((p.x - cx) / fx, (p.y - cy) / fy);
    return rays;
  }
  std::vector<cv::Point2d> normalized;
  const cv::TermCriteria criteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 50, 1e-12);
  if (model == DistortionModel::kEquidistant) {
    cv::fisheye::undistortPoints(pixels, normalized, intrinsicMatrix(), distortionCoefficients(),
                                 cv::noArray(), cv::noArray(), criteria);
  } else {
    cv::undistortPoints(pixels, normalized, intrinsicMatrix(), distortionCoefficients(),
                        cv::noArray(), cv::noArray(), criteria);
  }
  for (const auto& p : normalized) rays.emplace_back(p.x, p.y);
  return rays;
}

bool operator==(const CameraModel& a, const CameraModel& b) {
  return a.width == b.width && a.height == b.height && a.fx == b.fx && a.fy == b.fy &&
         a.cx == b.cx && a.cy == b.cy && a.model == b.model && a.distortion == b.distortion;
}

}  // namespace vicc_tracking
