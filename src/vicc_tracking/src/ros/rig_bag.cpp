#include "vicc_tracking/ros/rig_bag.hpp"

#include <algorithm>
#include <deque>
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

/// The encoding of the topic's first image ("" when it has none).
std::string firstEncoding(rosbag::Bag& bag, const std::string& topic) {
  rosbag::View view(bag, rosbag::TopicQuery(topic));
  for (const rosbag::MessageInstance& message : view) {
    if (const auto image = message.instantiate<sensor_msgs::Image>()) return image->encoding;
  }
  return "";
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
  // Image topics carrying a gray image (the pico flexx's image_mono8/image_mono16).
  std::set<std::string> gray_topics;
  for (const auto& [topic, topic_type] : topic_types) {
    if (topic_type == kImageType && isGrayEncoding(firstEncoding(bag_, topic))) {
      gray_topics.insert(topic);
    }
  }
  std::map<std::string, std::string> depth_types = topic_types;
  if (requested.depth.empty() && gray_topics.size() > 0) {
    // Leave the gray topics out of the depth's choice, unless they are all there is (a
    // driver may publish millimetre depth as mono16).
    std::map<std::string, std::string> without_gray;
    bool other_images = false;
    for (const auto& [topic, topic_type] : topic_types) {
      if (gray_topics.count(topic)) continue;
      without_gray[topic] = topic_type;
      other_images = other_images || topic_type == kImageType;
    }
    if (other_images) depth_types = without_gray;
  }
  topics_.depth = chooseTopic(depth_types, requested.depth, kImageType, true, "--depth-topic");
  if (requested.intensity == RigBagTopics::kNone) {
    topics_.intensity.clear();
  } else if (!requested.intensity.empty()) {
    topics_.intensity =
        chooseTopic(topic_types, requested.intensity, kImageType, true, "--intensity-topic");
    if (topics_.intensity == topics_.depth) {
      throw std::runtime_error("the intensity topic " + topics_.intensity + " is the depth topic");
    }
  } else {
    gray_topics.erase(topics_.depth);
    topics_.intensity = gray_topics.size() == 1 ? *gray_topics.begin() : "";
  }
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

void RigBag::forEachFrame(
    const std::function<void(const sensor_msgs::ImageConstPtr&,
                             const sensor_msgs::CameraInfoConstPtr&,
                             const sensor_msgs::ImageConstPtr&)>& on_frame) const {
  if (topics_.intensity.empty()) {
    forEachDepthFrame(
        [&](const sensor_msgs::ImageConstPtr& depth, const sensor_msgs::CameraInfoConstPtr& info) {
          on_frame(depth, info, nullptr);
        });
    return;
  }
  // Depth frames wait (in order) for their gray image until 1 s of bag time has passed;
  // gray images recorded before their depth wait as long.
  struct Pending {
    sensor_msgs::ImageConstPtr depth;
    sensor_msgs::CameraInfoConstPtr info;
    sensor_msgs::ImageConstPtr gray;
    ros::Time received;
  };
  const ros::Duration window(1.0);
  std::deque<Pending> pending;
  std::map<ros::Time, std::pair<sensor_msgs::ImageConstPtr, ros::Time>> early_gray;
  auto flush = [&](const ros::Time& now, bool all) {
    while (!pending.empty() &&
           (all || pending.front().gray || now - pending.front().received > window)) {
      on_frame(pending.front().depth, pending.front().info, pending.front().gray);
      pending.pop_front();
    }
    for (auto it = early_gray.begin(); it != early_gray.end();) {
      it = (all || now - it->second.second > window) ? early_gray.erase(it) : std::next(it);
    }
  };
  rosbag::View view(bag_,
                    rosbag::TopicQuery({topics_.depth, topics_.camera_info, topics_.intensity}));
  sensor_msgs::CameraInfoConstPtr info = first_camera_info_;
  for (const rosbag::MessageInstance& message : view) {
    const ros::Time now = message.getTime();
    if (message.getTopic() == topics_.camera_info) {
      if (auto latest = message.instantiate<sensor_msgs::CameraInfo>()) info = latest;
    } else if (message.getTopic() == topics_.depth) {
      if (auto image = message.instantiate<sensor_msgs::Image>()) {
        Pending frame{image, info, nullptr, now};
        const auto found = early_gray.find(image->header.stamp);
        if (found != early_gray.end()) {
          frame.gray = found->second.first;
          early_gray.erase(found);
        }
        pending.push_back(std::move(frame));
      }
    } else if (auto gray = message.instantiate<sensor_msgs::Image>()) {
      auto waiting = std::find_if(pending.begin(), pending.end(), [&](const Pending& frame) {
        return !frame.gray && frame.depth->header.stamp == gray->header.stamp;
      });
      if (waiting != pending.end()) {
        waiting->gray = gray;
      } else {
        early_gray[gray->header.stamp] = {gray, now};
      }
    }
    flush(now, false);
  }
  flush(ros::Time(), true);
}

}  // namespace vicc_tracking
