#pragma once
// Until surfel fusion exists, the reconstructed cloud is the union of the tracked frames'
// vertex and normal maps in the map frame, thinned on a voxel grid (PCL VoxelGrid).

#include <string>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Geometry>

#include "vicc_tracking/depth_preprocessing.hpp"

namespace vicc_fusion {

struct CloudAccumulatorConfig {
  double voxel_size = 0.004;  ///< m; the pico flexx sees ~2.5 mm per pixel at 0.5 m
  void validate() const;
};

class CloudAccumulator {
 public:
  explicit CloudAccumulator(const CloudAccumulatorConfig& config);

  /// Adds the valid vertices with normals of a full-resolution depth level, seen from
  /// camera_pose = T_map_camera.
  void addFrame(const vicc_tracking::DepthLevel& level, const Eigen::Isometry3d& camera_pose);

  /// The thinned cloud (one averaged point per occupied voxel).
  pcl::PointCloud<pcl::PointNormal> cloud() const;
  size_t rawPointCount() const { return points_.size(); }

 private:
  CloudAccumulatorConfig config_;
  pcl::PointCloud<pcl::PointNormal> points_;
};

/// Binary PLY with normals (MeshLab / CloudCompare). Throws std::runtime_error on failure.
void saveCloudPly(const std::string& path, const pcl::PointCloud<pcl::PointNormal>& cloud);

}  // namespace vicc_fusion
