#pragma once
// Depth map preprocessing (thesis 2.2.2): metric conversion, undistortion, bilateral
// filtering and the vertex / normal / radius maps of an image pyramid.

#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "vicc_tracking/camera_model.hpp"

namespace vicc_tracking {

struct PreprocessingConfig {
  int pyramid_levels = 3;  ///< 1..3, level 0 = full resolution
  double min_depth = 0.1;  ///< m; closer readings are invalid
  double max_depth = 4.0;  ///< m
  bool bilateral_filter = true;
  int bilateral_diameter = 5;           ///< px
  double bilateral_sigma_depth = 0.03;  ///< m
  double bilateral_sigma_space = 2.0;   ///< px
  double pyramid_depth_threshold =
      0.03;                         ///< m; depths further from the block's nearest are not averaged
  double normal_depth_jump = 0.05;  ///< m; neighbours further apart give no normal (depth edge)
  void validate() const;
};

/// Converts a raw depth image to metres: CV_32FC1 (metres) or CV_16UC1 (millimetres).
/// 0, NaN and +-Inf become 0 (invalid). Throws std::invalid_argument for other types.
cv::Mat1f toMetricDepth(const cv::Mat& raw);

/// Pinhole intrinsics of one pyramid level (images are undistorted).
struct PinholeIntrinsics {
  int width = 0;
  int height = 0;
  float fx = 0.f, fy = 0.f, cx = 0.f, cy = 0.f;
  PinholeIntrinsics halved() const;
};

/// Vertex, normal and radius maps of one level, row-major. Invalid pixels have z == 0 and a
/// zero normal.
struct DepthLevel {
  PinholeIntrinsics intrinsics;
  cv::Mat1f depth;
  std::vector<Eigen::Vector3f> vertices;
  std::vector<Eigen::Vector3f> normals;
  std::vector<float> radii;
  int valid_vertices = 0;
  int valid_normals = 0;

  bool hasVertex(int index) const { return vertices[index].z() > 0.f; }
  bool hasNormal(int index) const { return normals[index].z() != 0.f || normals[index].x() != 0.f; }
};

using DepthPyramid = std::vector<DepthLevel>;  ///< index 0 = finest

/// Builds the vertex/normal/radius maps of one level from an undistorted metric depth map.
/// rays (optional, one per pixel, row-major): the exact normalised ray (x/z, y/z) of the
/// sensor pixel each depth came from; without it the pinhole ray of the pixel centre is used.
DepthLevel computeDepthLevel(const cv::Mat1f& depth, const PinholeIntrinsics& intrinsics,
                             double normal_depth_jump,
                             const std::vector<Eigen::Vector2f>* rays = nullptr);

/// Undistorts, filters and builds the pyramid. Keeps the undistortion maps of the last camera
/// so consecutive frames of the same camera pay for them only once.
class DepthPreprocessor {
 public:
  explicit DepthPreprocessor(const PreprocessingConfig& config);

  void setCamera(const CameraModel& camera);
  bool hasCamera() const { return has_camera_; }
  const CameraModel& camera() const { return camera_; }
  const PreprocessingConfig& config() const { return config_; }

  /// raw: as delivered by the driver (distorted). Throws std::invalid_argument when the
  /// image type or size does not match the camera.
  DepthPyramid process(const cv::Mat& raw) const;

  /// The undistorted metric depth alone (used by fusion and tests).
  cv::Mat1f undistort(const cv::Mat1f& metric_depth) const;

  /// A per-pixel image of the sensor (e.g. the ToF amplitude / gray image) moved onto level
  /// 0's undistorted grid with the same nearest-sensor-pixel mapping as the depth, so each
  /// pixel's value belongs to the same sensor pixel as its depth. mono8 and mono16 (CV_8UC1,
  /// CV_16UC1) are scaled to [0, 1]; CV_32FC1 is kept as is, non-finite values become NaN.
  /// Pixels without a sensor pixel are NaN. Throws std::logic_error without a camera and
  /// std::invalid_argument when the size or type does not match.
  cv::Mat1f undistortIntensity(const cv::Mat& sensor_image) const;

 private:
  /// Throws std::logic_error without a camera, std::invalid_argument naming `what` when the
  /// image's size is not the camera's.
  void requireCameraSize(const cv::Mat& image, const char* what) const;

  PreprocessingConfig config_;
  CameraModel camera_;
  bool has_camera_ = false;
  cv::Mat undistort_map1_;
  cv::Mat undistort_map2_;
  /// Per pyramid level, computed once per camera: the exact ray of every sensor pixel, and
  /// for every pixel of the undistorted (pinhole) grid the sensor pixel it takes its data
  /// from (-1: none). Vertices and normals are computed on the sensor grid with exact rays
  /// and only then moved to the pinhole grid, so nearest-neighbour resampling never bends
  /// surfaces (it would put a depth on a ray up to half a pixel off: millimetres at grazing
  /// angles, enough to bias ICP rotations).
  struct LevelGeometry {
    PinholeIntrinsics intrinsics;
    std::vector<Eigen::Vector2f> sensor_rays;
    std::vector<int> source_index;
  };
  std::vector<LevelGeometry> levels_;
};

/// Halves a depth map: each 2x2 block becomes the mean of its depths that lie within
/// threshold of the block's nearest valid depth (no averaging across depth edges).
cv::Mat1f downsampleDepth(const cv::Mat1f& depth, float threshold);

}  // namespace vicc_tracking
