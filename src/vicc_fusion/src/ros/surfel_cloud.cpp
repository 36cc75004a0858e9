#include "vicc_fusion/ros/surfel_cloud.hpp"

#include <sensor_msgs/point_cloud2_iterator.h>

#include <cstring>

#include "vicc_fusion/ros/surfel_shading.hpp"

namespace vicc_fusion {

sensor_msgs::PointCloud2 toPointCloud2(const SurfelVector& surfels,
                                       const Eigen::Isometry3d& transform,
                                       const std::string& frame_id, const ros::Time& stamp) {
  sensor_msgs::PointCloud2 cloud;
  cloud.header.frame_id = frame_id;
  cloud.header.stamp = stamp;
  sensor_msgs::PointCloud2Modifier modifier(cloud);
  // rgb: a grey level shaded from the normal (rviz's RGB8 colouring shows the shape).
  modifier.setPointCloud2Fields(
      10, "x", 1, sensor_msgs::PointField::FLOAT32, "y", 1, sensor_msgs::PointField::FLOAT32, "z",
      1, sensor_msgs::PointField::FLOAT32, "normal_x", 1, sensor_msgs::PointField::FLOAT32,
      "normal_y", 1, sensor_msgs::PointField::FLOAT32, "normal_z", 1,
      sensor_msgs::PointField::FLOAT32, "radius", 1, sensor_msgs::PointField::FLOAT32, "confidence",
      1, sensor_msgs::PointField::FLOAT32, "intensity", 1, sensor_msgs::PointField::FLOAT32, "rgb",
      1, sensor_msgs::PointField::FLOAT32);
  modifier.resize(surfels.size());
  cloud.height = 1;
  cloud.width = static_cast<uint32_t>(surfels.size());
  cloud.is_dense = true;

  const Eigen::Isometry3f pose = transform.cast<float>();
  sensor_msgs::PointCloud2Iterator<float> position(cloud, "x");
  sensor_msgs::PointCloud2Iterator<float> normal(cloud, "normal_x");
  sensor_msgs::PointCloud2Iterator<float> radius(cloud, "radius");
  sensor_msgs::PointCloud2Iterator<float> confidence(cloud, "confidence");
  sensor_msgs::PointCloud2Iterator<float> intensity(cloud, "intensity");  // NaN: none
  sensor_msgs::PointCloud2Iterator<float> rgb(cloud, "rgb");
  for (const Surfel& surfel : surfels) {
    const Eigen::Vector3f p = pose * surfel.position;
    const Eigen::Vector3f n = pose.linear() * surfel.normal;
    position[0] = p.x(), position[1] = p.y(), position[2] = p.z();
    normal[0] = n.x(), normal[1] = n.y(), normal[2] = n.z();
    *radius = surfel.radius;
    *confidence = surfel.confidence;
    *intensity = surfel.intensity;
    const std::uint32_t grey = packedGrey(shadedGrey(n));
    std::memcpy(&*rgb, &grey, sizeof grey);
    ++position, ++normal, ++radius, ++confidence, ++intensity, ++rgb;
  }
  return cloud;
}

}  // namespace vicc_fusion
