#pragma once
// A depth image and the camera_info of the same stamp, delivered as one pair the way
// image_transport::CameraSubscriber delivers them, and built from its pieces: the image comes
// through image_transport (~image_transport selects raw, compressedDepth, ...), the info topic
// is `camera_info` beside the resolved image topic (image_transport::getCameraInfoTopic; a
// launch file that keeps camera_info elsewhere remaps that derived name), and
// message_filters pairs them by exact stamp.
//
// Why not CameraSubscriber itself: it keeps its synchronizer private, so a frame it cannot pair
// is dropped without a signal (its only complaint is a count comparison every 10 s, without
// stamps, and only when one topic outnumbers the pairs threefold). Here every unpaired message
// is reported with a throttled warning naming both topics, its stamp and the other topic's
// latest stamp. Messages older than the first pair are left out of it: they are the two
// connections coming up one after the other.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include <image_transport/image_transport.h>
#include <image_transport/subscriber_filter.h>
#include <message_filters/subscriber.h>
#include <message_filters/time_synchronizer.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>

namespace vicc_tracking {

class CameraSubscription {
 public:
  using Callback = std::function<void(const sensor_msgs::ImageConstPtr&,
                                      const sensor_msgs::CameraInfoConstPtr&)>;

  /// Subscribes `image_topic` (resolved and remapped in `nh`) and its sibling camera_info;
  /// `queue_size` bounds each subscription and the unpaired messages waiting for a partner.
  /// `label` starts the warnings ("tracker").
  CameraSubscription(ros::NodeHandle& nh, const std::string& image_topic, uint32_t queue_size,
                     const image_transport::TransportHints& hints, std::string label,
                     Callback callback);

  std::string imageTopic() const { return image_sub_.getTopic(); }
  std::string infoTopic() const { return info_sub_.getTopic(); }
  /// Messages dropped so far for want of a partner with their stamp (startup leftovers aside).
  std::size_t unpairedCount() const { return unpaired_; }

 private:
  void onPair(const sensor_msgs::ImageConstPtr& image, const sensor_msgs::CameraInfoConstPtr& info);
  void onUnpaired(const sensor_msgs::ImageConstPtr& image,
                  const sensor_msgs::CameraInfoConstPtr& info);
  void noteImage(const sensor_msgs::ImageConstPtr& image) { last_image_ = image->header.stamp; }
  void noteInfo(const sensor_msgs::CameraInfoConstPtr& info) { last_info_ = info->header.stamp; }

  const std::string label_;
  const Callback callback_;
  image_transport::ImageTransport transport_;
  image_transport::SubscriberFilter image_sub_;
  message_filters::Subscriber<sensor_msgs::CameraInfo> info_sub_;
  message_filters::TimeSynchronizer<sensor_msgs::Image, sensor_msgs::CameraInfo> sync_;

  std::optional<ros::Time> last_image_, last_info_;  ///< latest stamps, for the warnings
  std::size_t pairs_ = 0;
  ros::Time first_pair_;
  std::size_t unpaired_ = 0;
  std::size_t unreported_ = 0;  ///< unpaired since the last warning
  ros::WallTime last_warning_;
};

}  // namespace vicc_tracking
