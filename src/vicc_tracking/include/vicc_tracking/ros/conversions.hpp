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
/// Gray (amplitude) image as a cv::Mat header over the message data (no copy): CV_8UC1 for
/// mono8, CV_16UC1 for mono16/16UC1, CV_32FC1 for 32FC1. Throws std::invalid_argument for
/// other encodings, big-endian or truncated data. The message must outlive the Mat.
cv::Mat intensityImageView(const sensor_msgs::Image& image);
/// True for the encodings of a gray image besides the depth (mono8, mono16).
bool isGrayEncoding(const std::string& encoding);
/// A mono16 message from a CV_16UC1 image (the pico flexx's image_mono16).
sensor_msgs::Image mono16ImageMessage(const cv::Mat& gray);

/// REP-145 reading; rejects NaN/Inf and a zero stamp.
ImuSample imuSampleFromMessage(const sensor_msgs::Imu& imu);

Eigen::Isometry3d isometryFromTransform(const geometry_msgs::Transform& transform);
geometry_msgs::Transform transformFromIsometry(const Eigen::Isometry3d& pose);
geometry_msgs::Pose poseFromIsometry(const Eigen::Isometry3d& pose);

}  // namespace vicc_tracking
