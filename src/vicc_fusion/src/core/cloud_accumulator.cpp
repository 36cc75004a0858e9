#include "vicc_fusion/cloud_accumulator.hpp"

#include <stdexcept>

#include <pcl/filters/voxel_grid.h>
#include <pcl/io/ply_io.h>

namespace vicc_fusion {

void CloudAccumulatorConfig::validate() const {
  if (!(voxel_size > 0.0)) throw std::invalid_argument("voxel_size must be > 0");
}

CloudAccumulator::CloudAccumulator(const CloudAccumulatorConfig& config) : config_(config) {
  config_.validate();
}

void CloudAccumulator::addFrame(const vicc_tracking::DepthLevel& level,
                                const Eigen::Isometry3d& camera_pose) {
  const Eigen::Isometry3f pose = camera_pose.cast<float>();
  const Eigen::Matrix3f rotation = pose.linear();
  for (size_t i = 0; i < level.vertices.size(); ++i) {
    const int index = static_cast<int>(i);
    if (!level.hasVertex(index) || !level.hasNormal(index)) continue;
    const Eigen::Vector3f point = pose * level.vertices[i];
    const Eigen::Vector3f normal = rotation * level.normals[i];
    pcl::PointNormal p;
    p.x = point.x();
    p.y = point.y();
    p.z = point.z();
    p.normal_x = normal.x();
    p.normal_y = normal.y();
    p.normal_z = normal.z();
    p.curvature = 0.f;
    points_.push_back(p);
  }
}

pcl::PointCloud<pcl::PointNormal> CloudAccumulator::cloud() const {
  pcl::PointCloud<pcl::PointNormal> thinned;
  if (points_.empty()) return thinned;
  pcl::VoxelGrid<pcl::PointNormal> grid;
  const auto input = points_.makeShared();
  grid.setInputCloud(input);
  const float leaf = static_cast<float>(config_.voxel_size);
  grid.setLeafSize(leaf, leaf, leaf);
  grid.filter(thinned);
  for (auto& point : thinned) {
    // Averaged normals are shorter than 1 where views disagree; renormalise.
    const Eigen::Vector3f normal(point.normal_x, point.normal_y, point.normal_z);
    const float length = normal.norm();
    if (length > 1e-6f) {
      point.normal_x /= length;
      point.normal_y /= length;
      point.normal_z /= length;
    }
  }
  return thinned;
}

void saveCloudPly(const std::string& path, const pcl::PointCloud<pcl::PointNormal>& cloud) {
  if (cloud.empty()) throw std::runtime_error("the cloud is empty; nothing written to " + path);
  if (pcl::io::savePLYFileBinary(path, cloud) != 0) {
    throw std::runtime_error("cannot write " + path);
  }
}

}  // namespace vicc_fusion
