#pragma once
// The surfel model as sensor_msgs/PointCloud2: x y z normal_x normal_y normal_z radius
// confidence intensity (float32) and rgb (packed, a grey level shaded from the normal), the
// layout rviz and PCL understand.

#include <sensor_msgs/PointCloud2.h>
#include <Eigen/Geometry>

#include "vicc_fusion/surfel.hpp"

namespace vicc_fusion {

/// `transform` maps the model's frame into `frame_id` (e.g. the tracker's map alignment).
sensor_msgs::PointCloud2 toPointCloud2(const SurfelVector& surfels,
                                       const Eigen::Isometry3d& transform,
                                       const std::string& frame_id, const ros::Time& stamp);

}  // namespace vicc_fusion
