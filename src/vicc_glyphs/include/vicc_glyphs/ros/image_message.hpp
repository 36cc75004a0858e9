#pragma once
// ROS adapter of the renderer (kept out of the ROS-free core): rendered images as
// sensor_msgs/Image.

#include <sensor_msgs/Image.h>
#include <opencv2/core.hpp>
#include <string>

namespace vicc_glyphs {

/// Converts a rendered image (CV_32FC3 RGB in [0, 1], or CV_8UC3 RGB) to an rgb8 message with
/// step = 3 * width and the given frame id (stamp left zero for the caller to set).
/// Throws std::invalid_argument for other types.
sensor_msgs::Image toImageMsg(const cv::Mat& rgb, const std::string& frame_id = "");

}  // namespace vicc_glyphs
