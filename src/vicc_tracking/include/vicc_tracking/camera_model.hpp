#pragma once
// Pinhole camera with lens distortion, as described by sensor_msgs/CameraInfo.
// ROS-free: the ROS adapter fills it from a CameraInfo message.

#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace vicc_tracking {

enum class DistortionModel { kNone, kPlumbBob, kEquidistant };

/// Parses "plumb_bob", "rational_polynomial" is rejected, "equidistant", "" / "none".
DistortionModel distortionModelFromString(const std::string& name);
std::string toString(DistortionModel model);

struct CameraModel {
  int width = 0;
  int height = 0;
  double fx = 0.0;
  double fy = 0.0;
  double cx = 0.0;
  double cy = 0.0;
  DistortionModel model = DistortionModel::kNone;
  /// plumb_bob: k1 k2 t1 t2 k3; equidistant: k1 k2 k3 k4. Empty = no distortion.
  std::vector<double> distortion;

  /// Throws std::invalid_argument with a message naming the offending field.
  void validate() const;

  bool hasDistortion() const;
  cv::Matx33d intrinsicMatrix() const;
  cv::Mat distortionCoefficients() const;

  /// Pixel of a point in the camera frame, with distortion. Point must have z > 0.
  Eigen::Vector2d project(const Eigen::Vector3d& point_camera) const;
  /// Normalised image coordinates (x/z, y/z) of the ray seen at a distorted pixel.
  Eigen::Vector2d unprojectToNormalized(const Eigen::Vector2d& distorted_pixel) const;
  /// The same for every pixel centre of the image at once (row-major, width*height).
  std::vector<Eigen::Vector2d> normalizedRaysForAllPixels() const;
};

/// Same calibration: every field (size, fx, fy, cx, cy, distortion model and coefficients)
/// equal. The one test of "the camera changed" used by the tracker, the fusion node and the
/// offline tools, so a recalibration of any one value is never missed.
bool operator==(const CameraModel& a, const CameraModel& b);
inline bool operator!=(const CameraModel& a, const CameraModel& b) { return !(a == b); }

}  // namespace vicc_tracking
