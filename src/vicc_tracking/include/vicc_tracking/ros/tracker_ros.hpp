#pragma once
// ROS interface of the camera tracker, shared by the `tracker` node and nodelet. It owns no
// algorithm: messages are validated and converted, the core Tracker does the work, results
// are published. Bad input is reported with a throttled warning and dropped.

#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/Imu.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>

#include "vicc_tracking/ros/camera_subscription.hpp"
#include "vicc_tracking/tracker.hpp"
#include "vicc_tracking/tracker_parameters.hpp"

namespace vicc_tracking {

class LatestStatePublisher;
class TrackerReconfigure;

class TrackerRos {
 public:
  /// Who warns about parameters in the private namespace that no table knows: the tracker
  /// itself, or the node that embeds it and reads more parameters there (parameterNames()).
  enum class UnknownParameters { kWarn, kLeaveToOwner };

  /// Throws std::invalid_argument when a parameter is invalid.
  TrackerRos(ros::NodeHandle& nh, ros::NodeHandle& private_nh,
             UnknownParameters unknown_parameters = UnknownParameters::kWarn);
  ~TrackerRos();

  /// Called after every accepted depth frame, in the depth callback, with the tracker (its
  /// currentFrame() is the frame just tracked), the report, the depth message and
  /// T_published-map_tracker-map. Lets the fusion work on the frame without a copy and hand
  /// its model prediction back (frame-to-model) before the next frame arrives.
  using FrameHook =
      std::function<void(Tracker& tracker, const FrameReport& report,
                         const sensor_msgs::Image& depth, const Eigen::Isometry3d& map_alignment)>;
  void setFrameHook(FrameHook hook) { frame_hook_ = std::move(hook); }
  /// Holds each depth frame until `ready(stamp)` too (besides the IMU data up to its stamp), at
  /// most until ~max_pending_frames wait; whoever owns the condition calls processPending()
  /// when it may have changed. Lets the fusion wait for the gray image of the frame's stamp.
  void setFrameGate(std::function<bool(const ros::Time& stamp)> ready) {
    frame_gate_ = std::move(ready);
  }
  /// Processes the waiting depth frames whose inputs are all there (or that must go now).
  void processPending();
  const TrackerNodeSettings& settings() const { return settings_; }
  /// The resolved depth topic.
  std::string depthTopic() const { return camera_sub_->imageTopic(); }
  /// Resolved names of the parameters the tracker reads.
  const std::set<std::string>& parameterNames() const { return parameter_names_; }

 private:
  /// A depth image and the camera_info of its stamp.
  struct CameraFrame {
    sensor_msgs::ImageConstPtr depth;
    sensor_msgs::CameraInfoConstPtr info;
  };

  void onImu(const sensor_msgs::ImuConstPtr& imu);
  void onCameraFrame(const sensor_msgs::ImageConstPtr& depth,
                     const sensor_msgs::CameraInfoConstPtr& info);
  /// Takes the frame's calibration; false (warned) if its camera_info is invalid.
  bool useCameraInfo(const sensor_msgs::CameraInfo& info);

  bool ensureTracker(const std::string& camera_frame);
  /// Subscribes /tf and /tf_static anew (at most every few seconds) while a transform the
  /// tracker needs is missing: a latched /tf_static published at the moment the listener
  /// connects can be lost (roscpp's Publication::publish stores the latched message only
  /// after delivering it to the links it already had); a new subscription receives it again.
  void resubscribeTransforms();
  void processDepth(const CameraFrame& frame);
  void publish(const FrameReport& report, const sensor_msgs::Image& depth);
  void publishPose(const Eigen::Isometry3d& camera_pose, const ros::Time& stamp,
                   const std::string& camera_frame);
  Eigen::Isometry3d mapAlignment(const Eigen::Isometry3d& first_pose, const ros::Time& stamp);
  void forwardImu(const ImuSample& sample);

  std::set<std::string> parameter_names_;  // filled by the readers of config_ and settings_
  TrackerConfig config_;
  TrackerNodeSettings settings_;
  std::unique_ptr<TrackerReconfigure> reconfigure_;  ///< ~icp, ~ekf tuning while running
  FrameHook frame_hook_;
  std::function<bool(const ros::Time&)> frame_gate_;
  std::unique_ptr<Tracker> tracker_;
  std::optional<CameraModel> camera_;
  std::string imu_frame_;
  std::optional<double> last_imu_stamp_;
  std::deque<ImuSample> imu_before_tracker_;
  std::deque<CameraFrame> pending_frames_;
  Eigen::Isometry3d camera_to_child_ = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d map_alignment_ = Eigen::Isometry3d::Identity();
  std::optional<Eigen::Isometry3d> last_published_pose_;
  ros::Time last_published_stamp_;
  TrackingState last_state_ = TrackingState::kInitializing;

  tf2_ros::Buffer tf_buffer_;
  ros::NodeHandle tf_nh_;
  std::unique_ptr<tf2_ros::TransformListener> tf_listener_;
  ros::WallTime tf_subscribed_at_;
  tf2_ros::TransformBroadcaster tf_broadcaster_;
  /// depth/image (raw or e.g. compressedDepth, ~image_transport) + the camera_info beside it
  std::unique_ptr<CameraSubscription> camera_sub_;
  ros::Subscriber imu_sub_;
  ros::Publisher odom_pub_;
  ros::Publisher path_pub_;
  ros::Publisher status_pub_;
  nav_msgs::Path path_;
  std::unique_ptr<LatestStatePublisher> path_publication_;  ///< path_ on path_pub_, latest
};

}  // namespace vicc_tracking
