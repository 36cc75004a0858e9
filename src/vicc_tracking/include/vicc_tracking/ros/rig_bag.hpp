#pragma once
// Reads a depth + IMU recording (rosbag) for the offline tools: finds the topics, the
// IMU -> camera extrinsic on /tf_static, and hands the messages over in stamp order.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <rosbag/bag.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <Eigen/Geometry>

#include "vicc_tracking/imu_types.hpp"

namespace vicc_tracking {

struct RigBagTopics {
  std::string depth;        ///< sensor_msgs/Image
  std::string camera_info;  ///< sensor_msgs/CameraInfo
  std::string imu;          ///< sensor_msgs/Imu; empty = the bag has none
  /// The gray (amplitude) image, a mono8/mono16 sensor_msgs/Image. Requested: empty = the
  /// only such topic besides the depth if there is exactly one, kNone = none. Detected:
  /// empty = none.
  std::string intensity;
  static constexpr const char* kNone = "none";
};

class RigBag {
 public:
  /// Empty topic names are filled with the only topic of that type in the bag (for the
  /// depth, gray mono8/mono16 Image topics are left out when others exist). Throws
  /// std::runtime_error when the bag cannot be read, a named topic is missing or has the
  /// wrong type, or the choice is ambiguous (the message lists the candidates).
  RigBag(const std::string& path, const RigBagTopics& requested);

  const RigBagTopics& topics() const { return topics_; }
  size_t depthFrameCount() const { return depth_count_; }
  const std::string& imuFrame() const { return imu_frame_; }
  const std::string& cameraFrame() const { return camera_frame_; }

  /// All IMU readings, sorted by stamp. Invalid readings are skipped and counted.
  const std::vector<ImuSample>& imuSamples() const { return imu_samples_; }
  int invalidImuReadings() const { return invalid_imu_; }

  /// T_imu_camera from the bag's /tf_static (and /tf), if present.
  std::optional<Eigen::Isometry3d> imuToCamera() const { return imu_to_camera_; }

  /// Calls on_frame for every depth image in bag order, with the latest camera_info
  /// received before it (the first in the bag for images recorded before any).
  void forEachDepthFrame(
      const std::function<void(const sensor_msgs::ImageConstPtr&,
                               const sensor_msgs::CameraInfoConstPtr&)>& on_frame) const;

  /// As forEachDepthFrame, with the gray image of the same header stamp (topics().intensity;
  /// null when there is none for the frame). Gray images are looked for up to 1 s of bag
  /// time around their depth image, whichever was recorded first.
  void forEachFrame(const std::function<void(const sensor_msgs::ImageConstPtr&,
                                             const sensor_msgs::CameraInfoConstPtr&,
                                             const sensor_msgs::ImageConstPtr&)>& on_frame) const;

 private:
  void detectTopics(const RigBagTopics& requested);
  void readImuAndExtrinsic();

  std::string path_;
  mutable rosbag::Bag bag_;
  RigBagTopics topics_;
  size_t depth_count_ = 0;
  std::string imu_frame_;
  std::string camera_frame_;
  std::vector<ImuSample> imu_samples_;
  int invalid_imu_ = 0;
  std::optional<Eigen::Isometry3d> imu_to_camera_;
  sensor_msgs::CameraInfoConstPtr first_camera_info_;
};

}  // namespace vicc_tracking
