#pragma once
// Conversions between ROS messages and the ROS-free core types. Every function that takes
// a message validates it and throws std::invalid_argument with a message that says what is
// wrong, so callers can warn and keep running.

#include <string>

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/Transform.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/Imu.h>
#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "vicc_tracking/camera_model.hpp"
#include "vicc_tracking/imu_types.hpp"

namespace vicc_tracking {

CameraModel cameraModelFromInfo(const sensor_msgs::CameraInfo& info);
sensor_msgs::CameraInfo cameraInfoFromModel(const CameraModel& camera);

/// Depth image as a cv::Mat header over the message data (no copy): CV_32FC1 metres for
/// 32FC1, CV_16UC1 millimetres for 16UC1/mono16. The message must outlive the Mat.
cv::Mat depthImageView(const sensor_msgs::Image& image);
/// A 32FC1 depth message (metres) from a CV_32FC1 image.
sensor_msgs::Image depthImageMessage(const cv::Mat& depth_metres);

/// REP-145 reading; rejects NaN/Inf and a zero stamp.
ImuSample imuSampleFromMessage(const sensor_msgs::Imu& imu);

Eigen::Isometry3d isometryFromTransform(const geometry_msgs::Transform& transform);
geometry_msgs::Transform transformFromIsometry(const Eigen::Isometry3d& pose);
geometry_msgs::Pose poseFromIsometry(const Eigen::Isometry3d& pose);

}  // namespace vicc_tracking
