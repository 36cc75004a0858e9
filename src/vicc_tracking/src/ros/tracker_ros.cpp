#include "vicc_tracking/ros/tracker_ros.hpp"

#include <nav_msgs/Odometry.h>
#include <vicc_msgs/TrackingStatus.h>

#include "vicc_common/ros_parameters.hpp"
#include "vicc_tracking/ros/conversions.hpp"
#include "vicc_tracking/ros/latest_state_publisher.hpp"
#include "vicc_tracking/ros/parameters.hpp"
#include "vicc_tracking/ros/status_message.hpp"
#include "vicc_tracking/ros/tracker_reconfigure.hpp"

namespace vicc_tracking {
namespace {
constexpr double kWarnPeriod = 5.0;  // s between repeats of the same warning
constexpr double kTfResubscribePeriod = 2.0;  // wall s between re-subscriptions to tf
}

TrackerRos::TrackerRos(ros::NodeHandle& nh, ros::NodeHandle& private_nh,
                       UnknownParameters unknown_parameters)
    : config_(readTrackerConfig(private_nh, parameter_names_)),
      settings_(readTrackerNodeSettings(private_nh, parameter_names_)),
      reconfigure_(std::make_unique<TrackerReconfigure>(private_nh, config_)),
      tf_nh_(nh),
      tf_listener_(std::make_unique<tf2_ros::TransformListener>(tf_buffer_, nh)),
      tf_subscribed_at_(ros::WallTime::now()) {
  if (unknown_parameters == UnknownParameters::kWarn) {
    vicc_common::warnUnknownRosParameters(private_nh, parameter_names_);
  }
  odom_pub_ = private_nh.advertise<nav_msgs::Odometry>("odom", 10);
  path_pub_ = private_nh.advertise<nav_msgs::Path>("path", 1, true);
  path_publication_ = std::make_unique<LatestStatePublisher>(
      private_nh, path_pub_, 0.0, [this](const ros::Time&) { path_pub_.publish(path_); });
  status_pub_ = private_nh.advertise<vicc_msgs::TrackingStatus>("status", 50);
  // IMU at up to 400 Hz must not be dropped while a depth frame is processed.
  imu_sub_ =
      nh.subscribe("imu", 2000, &TrackerRos::onImu, this, ros::TransportHints().tcpNoDelay());
  // Depth and the camera_info of the same stamp, as image_transport pairs them: a recording
  // or driver with compressedDepth works with ~image_transport:=compressedDepth. Not lazy: tf
  // and odometry are always wanted.
  camera_sub_ = std::make_unique<CameraSubscription>(
      nh, "depth/image", 10,
      image_transport::TransportHints("raw", ros::TransportHints(), private_nh), "tracker",
      [this](const sensor_msgs::ImageConstPtr& depth, const sensor_msgs::CameraInfoConstPtr& info) {
        onCameraFrame(depth, info);
      });
  path_.header.frame_id = settings_.map_frame;
  ROS_INFO(
      "tracker: init strategy '%s', %d pyramid level(s); depth on %s, camera_info on %s, "
      "IMU on %s",
      toString(config_.init_strategy).c_str(), config_.preprocessing.pyramid_levels,
      camera_sub_->imageTopic().c_str(), camera_sub_->infoTopic().c_str(),
      imu_sub_.getTopic().c_str());
}

TrackerRos::~TrackerRos() = default;

bool TrackerRos::useCameraInfo(const sensor_msgs::CameraInfo& info) {
  try {
    const CameraModel camera = cameraModelFromInfo(info);
    if (camera_ && *camera_ == camera) return true;
    if (camera_) ROS_WARN("tracker: camera_info changed; using the new calibration");
    camera_ = camera;
    if (tracker_) tracker_->setCamera(camera);
    return true;
  } catch (const std::exception& error) {
    ROS_WARN_THROTTLE(kWarnPeriod,
                      "tracker: depth frame at %.6f dropped, its camera_info on %s: %s",
                      info.header.stamp.toSec(), camera_sub_->infoTopic().c_str(), error.what());
    return false;
  }
}

void TrackerRos::onImu(const sensor_msgs::ImuConstPtr& imu) {
  ImuSample sample;
  try {
    sample = imuSampleFromMessage(*imu);
  } catch (const std::exception& error) {
    ROS_WARN_THROTTLE(kWarnPeriod, "tracker: ignoring IMU message: %s", error.what());
    return;
  }
  if (imu_frame_.empty()) imu_frame_ = imu->header.frame_id;
  if (last_imu_stamp_ && sample.stamp < *last_imu_stamp_ - config_.synchronizer.clock_jump) {
    // A looping bag: frames queued from the old loop would be out of order now.
    pending_frames_.clear();
    imu_before_tracker_.clear();
    last_imu_stamp_ = sample.stamp;
  } else if (!last_imu_stamp_ || sample.stamp > *last_imu_stamp_) {
    last_imu_stamp_ = sample.stamp;  // a late reading must not hold depth frames back
  }
  forwardImu(sample);
  processPending();
}

void TrackerRos::forwardImu(const ImuSample& sample) {
  if (!tracker_) {
    imu_before_tracker_.push_back(sample);
    const size_t max_buffered = 4000;  // ~10 s at 400 Hz
    while (imu_before_tracker_.size() > max_buffered) imu_before_tracker_.pop_front();
    return;
  }
  const ImuAddResult result = tracker_->addImu(sample);
  switch (result) {
    case ImuAddResult::kAccepted:
    case ImuAddResult::kFirst:
      break;
    case ImuAddResult::kClockJump:
      ROS_WARN("tracker: IMU clock jumped back (looping bag?); tracking restarts");
      path_.poses.clear();
      last_published_pose_.reset();
      break;
    default:
      ROS_WARN_THROTTLE(kWarnPeriod, "tracker: IMU reading at %.6f: %s", sample.stamp,
                        toString(result));
  }
}

void TrackerRos::onCameraFrame(const sensor_msgs::ImageConstPtr& depth,
                               const sensor_msgs::CameraInfoConstPtr& info) {
  pending_frames_.push_back({depth, info});
  processPending();
}

void TrackerRos::resubscribeTransforms() {
  const ros::WallTime now = ros::WallTime::now();
  if ((now - tf_subscribed_at_).toSec() < kTfResubscribePeriod) return;
  tf_listener_.reset();  // joins its thread before the new one subscribes
  tf_listener_ = std::make_unique<tf2_ros::TransformListener>(tf_buffer_, tf_nh_);
  tf_subscribed_at_ = now;
  ROS_INFO_THROTTLE(kWarnPeriod, "tracker: subscribed to /tf and /tf_static again (a latched "
                                 "transform can be missed by a subscriber joining as it is "
                                 "published)");
}

bool TrackerRos::ensureTracker(const std::string& camera_frame) {
  if (tracker_) return true;
  const bool imu_used = config_.wait_for_imu || needsImu(config_.init_strategy);
  Eigen::Isometry3d imu_to_camera = Eigen::Isometry3d::Identity();
  if (imu_used) {
    if (imu_frame_.empty()) {
      ROS_WARN_THROTTLE(kWarnPeriod, "tracker: waiting for IMU messages on %s",
                        imu_sub_.getTopic().c_str());
      return false;
    }
    try {
      imu_to_camera = isometryFromTransform(
          tf_buffer_.lookupTransform(imu_frame_, camera_frame, ros::Time(0)).transform);
    } catch (const std::exception& error) {
      ROS_WARN_THROTTLE(kWarnPeriod,
                        "tracker: no IMU -> camera extrinsic on tf (%s -> %s): %s. Publish it on "
                        "/tf_static.",
                        imu_frame_.c_str(), camera_frame.c_str(), error.what());
      resubscribeTransforms();
      return false;
    }
  }
  const std::string child = !settings_.tf_child_frame.empty()
                                ? settings_.tf_child_frame
                                : (imu_used ? imu_frame_ : camera_frame);
  if (child != camera_frame) {
    try {
      camera_to_child_ = isometryFromTransform(
          tf_buffer_.lookupTransform(camera_frame, child, ros::Time(0)).transform);
    } catch (const std::exception& error) {
      ROS_WARN_THROTTLE(kWarnPeriod, "tracker: no transform %s -> %s on tf: %s",
                        camera_frame.c_str(), child.c_str(), error.what());
      resubscribeTransforms();
      return false;
    }
  }
  settings_.tf_child_frame = child;
  tracker_ = std::make_unique<Tracker>(config_, imu_to_camera);
  if (camera_) tracker_->setCamera(*camera_);
  for (const ImuSample& sample : imu_before_tracker_) forwardImu(sample);
  imu_before_tracker_.clear();
  ROS_INFO("tracker: ready; publishing %s -> %s", settings_.map_frame.c_str(), child.c_str());
  return true;
}

void TrackerRos::processPending() {
  const bool imu_used = config_.wait_for_imu || needsImu(config_.init_strategy);
  while (!pending_frames_.empty()) {
    const CameraFrame frame = pending_frames_.front();
    const ros::Time& stamp = frame.depth->header.stamp;
    const bool imu_caught_up = !imu_used || (last_imu_stamp_ && *last_imu_stamp_ >= stamp.toSec());
    const bool gate_open = !frame_gate_ || frame_gate_(stamp);
    const bool queue_full = static_cast<int>(pending_frames_.size()) > settings_.max_pending_frames;
    if (!(imu_caught_up && gate_open) && !queue_full) return;
    if (!imu_caught_up) {
      ROS_WARN_THROTTLE(kWarnPeriod,
                        "tracker: no IMU data up to depth stamp %.3f; processing "
                        "with the IMU data received so far",
                        stamp.toSec());
    }
    pending_frames_.pop_front();
    processDepth(frame);
  }
}

void TrackerRos::processDepth(const CameraFrame& frame) {
  const sensor_msgs::ImageConstPtr& depth = frame.depth;
  reconfigure_->applyPending(config_, tracker_.get());
  if (depth->header.frame_id.empty()) {
    ROS_WARN_THROTTLE(kWarnPeriod, "tracker: depth image without frame_id dropped");
    return;
  }
  if (!useCameraInfo(*frame.info)) return;
  if (!ensureTracker(depth->header.frame_id)) return;
  FrameReport report;
  try {
    report = tracker_->addDepth(depth->header.stamp.toSec(), depthImageView(*depth));
  } catch (const std::exception& error) {
    ROS_WARN_THROTTLE(kWarnPeriod, "tracker: depth image dropped: %s", error.what());
    return;
  }
  if (!report.accepted) {
    ROS_WARN_THROTTLE(kWarnPeriod, "tracker: depth frame at %.6f dropped: %s",
                      depth->header.stamp.toSec(), report.message.c_str());
    return;
  }
  publish(report, *depth);
  if (frame_hook_) frame_hook_(*tracker_, report, *depth, map_alignment_);
}

Eigen::Isometry3d TrackerRos::mapAlignment(const Eigen::Isometry3d& first_pose,
                                           const ros::Time& stamp) {
  if (settings_.initial_pose_frame.empty()) return Eigen::Isometry3d::Identity();
  try {
    const Eigen::Isometry3d reference = isometryFromTransform(
        tf_buffer_
            .lookupTransform(settings_.map_frame, settings_.initial_pose_frame, stamp,
                             ros::Duration(0.2))
            .transform);
    return reference * first_pose.inverse();
  } catch (const std::exception& error) {
    ROS_WARN("tracker: cannot align the map to %s: %s", settings_.initial_pose_frame.c_str(),
             error.what());
    return Eigen::Isometry3d::Identity();
  }
}

void TrackerRos::publish(const FrameReport& report, const sensor_msgs::Image& depth) {
  vicc_msgs::TrackingStatus status = statusMessage(report, config_.init_strategy);
  status.header.stamp = depth.header.stamp;
  status.header.frame_id = settings_.map_frame;
  status_pub_.publish(status);

  if (report.state != last_state_) {
    if (report.state == TrackingState::kLost) {
      ROS_WARN("tracker: tracking lost at %.3f: %s", depth.header.stamp.toSec(),
               report.message.c_str());
    } else if (report.state == TrackingState::kOk) {
      ROS_INFO("tracker: tracking %s",
               last_state_ == TrackingState::kLost ? "recovered" : "started");
    }
    last_state_ = report.state;
  }
  if (!report.tracked()) {
    const std::string warning = tracker_->calibrationWarning();
    if (!warning.empty()) ROS_WARN_THROTTLE(kWarnPeriod, "tracker: %s", warning.c_str());
    return;
  }
  if (report.frame_index == 0) {
    map_alignment_ = mapAlignment(report.camera_pose, depth.header.stamp);
    path_.poses.clear();
    last_published_pose_.reset();
  }
  publishPose(map_alignment_ * report.camera_pose, depth.header.stamp, depth.header.frame_id);
}

void TrackerRos::publishPose(const Eigen::Isometry3d& camera_pose, const ros::Time& stamp,
                             const std::string& camera_frame) {
  if (settings_.publish_tf) {
    geometry_msgs::TransformStamped transform;
    transform.header.stamp = stamp;
    transform.header.frame_id = settings_.map_frame;
    transform.child_frame_id = settings_.tf_child_frame;
    transform.transform = transformFromIsometry(camera_pose * camera_to_child_);
    tf_broadcaster_.sendTransform(transform);
  }

  nav_msgs::Odometry odom;
  odom.header.stamp = stamp;
  odom.header.frame_id = settings_.map_frame;
  odom.child_frame_id = camera_frame;
  odom.pose.pose = poseFromIsometry(camera_pose);
  if (last_published_pose_ && stamp > last_published_stamp_) {
    // Twist in the child frame from the last two poses.
    const double dt = (stamp - last_published_stamp_).toSec();
    const Eigen::Isometry3d delta = last_published_pose_->inverse() * camera_pose;
    const Eigen::AngleAxisd rotation(delta.linear());
    const Eigen::Vector3d angular = rotation.axis() * rotation.angle() / dt;
    const Eigen::Vector3d linear =
        camera_pose.linear().transpose() *
        (camera_pose.translation() - last_published_pose_->translation()) / dt;
    odom.twist.twist.linear.x = linear.x();
    odom.twist.twist.linear.y = linear.y();
    odom.twist.twist.linear.z = linear.z();
    odom.twist.twist.angular.x = angular.x();
    odom.twist.twist.angular.y = angular.y();
    odom.twist.twist.angular.z = angular.z();
  }
  odom_pub_.publish(odom);
  last_published_pose_ = camera_pose;
  last_published_stamp_ = stamp;

  geometry_msgs::PoseStamped pose;
  pose.header = odom.header;
  pose.pose = odom.pose.pose;
  path_.header.stamp = stamp;
  path_.poses.push_back(pose);
  if (static_cast<int>(path_.poses.size()) > settings_.max_path_length) {
    path_.poses.erase(path_.poses.begin());
  }
  path_publication_->changed(stamp);
}

}  // namespace vicc_tracking
