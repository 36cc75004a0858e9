#include "vicc_tracking/ros/camera_subscription.hpp"

#include <cstdio>
#include <utility>

#include <image_transport/camera_common.h>

namespace vicc_tracking {
namespace {

const ros::WallDuration kWarnPeriod(5.0);  // between two unpaired-frame warnings

std::string stampText(const ros::Time& stamp) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.6f", stamp.toSec());
  return text;
}

std::string latestText(const std::optional<ros::Time>& latest) {
  return latest ? "its latest at " + stampText(*latest) : "none received yet";
}

}  // namespace

CameraSubscription::CameraSubscription(ros::NodeHandle& nh, const std::string& image_topic,
                                       uint32_t queue_size,
                                       const image_transport::TransportHints& hints,
                                       std::string label, Callback callback)
    : label_(std::move(label)), callback_(std::move(callback)), transport_(nh), sync_(queue_size) {
  // As CameraSubscriber: remap the image topic first, then take camera_info beside it.
  const std::string resolved_image = nh.resolveName(image_topic);
  image_sub_.subscribe(transport_, resolved_image, queue_size, hints);
  info_sub_.subscribe(nh, image_transport::getCameraInfoTopic(resolved_image), queue_size,
                      hints.getRosHints());
  image_sub_.registerCallback(&CameraSubscription::noteImage, this);
  info_sub_.registerCallback(&CameraSubscription::noteInfo, this);
  sync_.connectInput(image_sub_, info_sub_);
  sync_.registerCallback(&CameraSubscription::onPair, this);
  sync_.registerDropCallback(&CameraSubscription::onUnpaired, this);
}

void CameraSubscription::onPair(const sensor_msgs::ImageConstPtr& image,
                                const sensor_msgs::CameraInfoConstPtr& info) {
  if (pairs_++ == 0) first_pair_ = image->header.stamp;
  callback_(image, info);
}

void CameraSubscription::onUnpaired(const sensor_msgs::ImageConstPtr& image,
                                    const sensor_msgs::CameraInfoConstPtr& info) {
  if (!image && !info) return;
  const ros::Time stamp = image ? image->header.stamp : info->header.stamp;
  // The first pair drops what came before it on one connection only.
  if (pairs_ == 1 && stamp < first_pair_) {
    ROS_DEBUG("%s: unpaired %s at %s before the first pair (connections starting)", label_.c_str(),
              image ? "depth image" : "camera_info", stampText(stamp).c_str());
    return;
  }
  ++unpaired_;
  ++unreported_;
  const ros::WallTime now = ros::WallTime::now();
  if (!last_warning_.isZero() && now - last_warning_ < kWarnPeriod) return;
  const std::string more =
      unreported_ > 1 ? " (" + std::to_string(unreported_ - 1) + " more since the last warning)"
                      : "";
  if (image) {
    ROS_WARN(
        "%s: depth image at %s on %s has no camera_info with the same stamp on %s (%s); "
        "frame dropped%s. Image and camera_info are paired by exact stamp.",
        label_.c_str(), stampText(stamp).c_str(), imageTopic().c_str(), infoTopic().c_str(),
        latestText(last_info_).c_str(), more.c_str());
  } else {
    ROS_WARN(
        "%s: camera_info at %s on %s has no depth image with the same stamp on %s (%s); "
        "dropped%s. Image and camera_info are paired by exact stamp.",
        label_.c_str(), stampText(stamp).c_str(), infoTopic().c_str(), imageTopic().c_str(),
        latestText(last_image_).c_str(), more.c_str());
  }
  last_warning_ = now;
  unreported_ = 0;
}

}  // namespace vicc_tracking
