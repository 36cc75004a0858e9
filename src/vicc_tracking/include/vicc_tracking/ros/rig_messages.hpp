#pragma once
// The messages the real pico flexx + IMU drivers publish, built from the rig simulator.
// Shared by the depth_publisher / imu_publisher nodes and vicc_make_bag so a live
// simulation and a recorded bag carry identical data.

#include <geometry_msgs/TransformStamped.h>
#include <ros/time.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/Imu.h>

#include "vicc_tracking/sim/rig_simulator.hpp"

namespace vicc_tracking {

/// Topic names of the real drivers.
struct RigTopics {
  static constexpr const char* kDepth = "/pico_flexx/image_depth";
  static constexpr const char* kGray = "/pico_flexx/image_mono16";  ///< amplitude, mono16
  static constexpr const char* kCameraInfo = "/pico_flexx/camera_info";
  static constexpr const char* kImu = "/imu/data_raw";
};

sensor_msgs::Image rigDepthMessage(const sim::RigSimulator& rig, int frame_index,
                                   const ros::Time& stamp);
/// One frame's depth (32FC1) and amplitude (mono16) images, same header.
struct RigImages {
  sensor_msgs::Image depth;
  sensor_msgs::Image gray;
};
RigImages rigImageMessages(const sim::RigSimulator& rig, int frame_index, const ros::Time& stamp);
sensor_msgs::CameraInfo rigCameraInfo(const sim::RigSimulator& rig, const ros::Time& stamp);
sensor_msgs::Imu rigImuMessage(const sim::RigSimulator& rig, int sample_index,
                               const ros::Time& stamp);
/// imu_link -> camera optical frame (for /tf_static).
geometry_msgs::TransformStamped rigExtrinsic(const sim::RigSimulator& rig, const ros::Time& stamp);
/// map -> <camera frame>_gt at relative time t (for /tf).
geometry_msgs::TransformStamped rigGroundTruth(const sim::RigSimulator& rig, double t,
                                               const ros::Time& stamp);
std::string groundTruthFrame(const sim::Scenario& scenario);

}  // namespace vicc_tracking
