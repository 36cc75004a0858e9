#include "vicc_tracking/ros/rig_bag.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>

#include <rosbag/view.h>
#include <sensor_msgs/Imu.h>
#include <tf2/buffer_core.h>
#include <tf2_msgs/TFMessage.h>

#include "vicc_tracking/ros/conversions.hpp"

namespace vicc_tracking {
namespace {

const char* kImageType = "sensor_msgs/Image";
const char* kInfoType = "sensor_msgs/CameraInfo";
const char* kImuType = "sensor_msgs/Imu";

std::string chooseTopic(const std::map<std::string, std::string>& topic_types,
                        const std::string& requested, const std::string& type, bool required,
                        const std::string& option) {
  if (!requested.empty()) {
    const auto found = topic_types.find(requested);
    if (found == topic_types.end()) {
      throw std::runtime_error("topic " + requested + " is not in the bag");
    }
    if (found->second != type) {
      throw std::runtime_error("topic " + requested + " has type " + found->second + ", expected " +
                               type);
    }
    return requested;
  }
  std::vector<std::string> candidates;
  for (const auto& [topic, topic_type] : topic_types) {
    if (topic_type == type) candidates.push_back(topic);
  }
  if (candidates.size() == 1) return candidates.front();
  if (candidates.empty()) {
    if (!required) return "";
    throw std::runtime_error("the bag has no " + type + " topic");
  }
  std::string list;
  for (const auto& candidate : candidates) list += " " + candidate;
  throw std::runtime_error("the bag has several " + type + " topics (" + list +
                           " ); choose one with " + option);
}

}  // namespace

RigBag::RigBag(const std::string& path, const RigBagTopics& requested) : path_(path) {
  try {
    bag_.open(path, rosbag::bagmode::Read);
  } catch (const std::exception& error) {
    throw std::runtime_error("cannot read bag " + path + ": " + error.what());
  }
  detectTopics(requested);
  readImuAndExtrinsic();
}

void RigBag::detectTopics(const RigBagTopics& requested) {
  rosbag::View all(bag_);
  std::map<std::string, std::string> topic_types;
  for (const rosbag::ConnectionInfo* connection : all.getConnections()) {
    topic_types[connection->topic] = connection->datatype;
  }
  topics_.depth = chooseTopic(topic_types, requested.depth, kImageType, true, "--depth-topic");
  topics_.camera_info =
      chooseTopic(topic_types, requested.camera_info, kInfoType, true, "--info-topic");
  topics_.imu = chooseTopic(topic_types, requested.imu, kImuType, false, "--imu-topic");
  rosbag::View depth_view(bag_, rosbag::TopicQuery(topics_.depth));
  depth_count_ = depth_view.size();
  if (depth_count_ == 0) throw std::runtime_error("topic " + topics_.depth + " has no messages");
  for (const rosbag::MessageInstance& message : depth_view) {
    const auto image = message.instantiate<sensor_msgs::Image>();
    if (image && !image->header.frame_id.empty()) {
      camera_frame_ = image->header.frame_id;
      break;
    }
  }
  // camera_info is constant in practice and may be recorded just after the first image.
  rosbag::View info_view(bag_, rosbag::TopicQuery(topics_.camera_info));
  for (const rosbag::MessageInstance& message : info_view) {
    if ((first_camera_info_ = message.instantiate<sensor_msgs::CameraInfo>())) break;
  }
}

void RigBag::readImuAndExtrinsic() {
  tf2::BufferCore tf_buffer(ros::Duration(1e6));
  std::vector<std::string> topics{"/tf_static", "/tf"};
  if (!topics_.imu.empty()) topics.push_back(topics_.imu);
  rosbag::View view(bag_, rosbag::TopicQuery(topics));
  for (const rosbag::MessageInstance& message : view) {
    if (message.getTopic() == topics_.imu) {
      const auto imu = message.instantiate<sensor_msgs::Imu>();
      if (!imu) continue;
      try {
        imu_samples_.push_back(imuSampleFromMessage(*imu));
        if (imu_frame_.empty()) imu_frame_ = imu->header.frame_id;
      } catch (const std::exception&) {
        ++invalid_imu_;
      }
      continue;
    }
    const auto tf = message.instantiate<tf2_msgs::TFMessage>();
    if (!tf) continue;
    const bool is_static = message.getTopic() == "/tf_static";
    for (const auto& transform : tf->transforms) {
      try {
        tf_buffer.setTransform(transform, "bag", is_static);
      } catch (const std::exception&) {
        // A malformed transform in the bag does not matter unless it is the one we need.
      }
    }
  }
  // Recording order can differ slightly from stamp order.
  std::stable_sort(imu_samples_.begin(), imu_samples_.end(),
                   [](const ImuSample& a, const ImuSample& b) { return a.stamp < b.stamp; });
  if (imu_frame_.empty() || camera_frame_.empty()) return;
  try {
    imu_to_camera_ = isometryFromTransform(
        tf_buffer.lookupTransform(imu_frame_, camera_frame_, ros::Time(0)).transform);
  } catch (const std::exception&) {
    imu_to_camera_.reset();
  }
}

void RigBag::forEachDepthFrame(
    const std::function<void(const sensor_msgs::ImageConstPtr&,
                             const sensor_msgs::CameraInfoConstPtr&)>& on_frame) const {
  rosbag::View view(bag_, rosbag::TopicQuery({topics_.depth, topics_.camera_info}));
  sensor_msgs::CameraInfoConstPtr info = first_camera_info_;
  for (const rosbag::MessageInstance& message : view) {
    if (message.getTopic() == topics_.camera_info) {
      if (auto latest = message.instantiate<sensor_msgs::CameraInfo>()) info = latest;
      continue;
    }
    if (auto image = message.instantiate<sensor_msgs::Image>()) on_frame(image, info);
  }
}

}  // namespace vicc_tracking
