// rostest: the tracker node follows the simulated rig's ground truth, and bad messages
// mixed into its inputs are dropped without disturbing it. Among them a depth image and a
// camera_info whose stamps do not match: neither is used, and the node says so on /rosout,
// naming both topics and the stamp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Log.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/image_encodings.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>
#include <vicc_msgs/TrackingStatus.h>

#include "graph_queries.hpp"
#include "vicc_tracking/ros/conversions.hpp"
#include "vicc_tracking/tracker.hpp"
#include "wait_for_recording_end.hpp"

namespace {

std::string stampText(const ros::Time& stamp) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.6f", stamp.toSec());
  return text;
}

struct PoseSample {
  ros::Time stamp;
  Eigen::Isometry3d pose;
};

class TrackerNodeTest : public ::testing::Test {
 protected:
  TrackerNodeTest() : listener_(buffer_) {
    odom_sub_ = nh_.subscribe("/tracker/odom", 1000, &TrackerNodeTest::onOdom, this);
    status_sub_ = nh_.subscribe("/tracker/status", 1000, &TrackerNodeTest::onStatus, this);
    info_sub_ = nh_.subscribe("/pico_flexx/camera_info", 10, &TrackerNodeTest::onInfo, this);
    depth_sub_ = nh_.subscribe("/pico_flexx/image_depth", 10, &TrackerNodeTest::onDepth, this);
    rosout_sub_ = nh_.subscribe("/rosout", 1000, &TrackerNodeTest::onLog, this);
    bad_depth_pub_ = nh_.advertise<sensor_msgs::Image>("/pico_flexx/image_depth", 10);
    bad_info_pub_ = nh_.advertise<sensor_msgs::CameraInfo>("/pico_flexx/camera_info", 10);
    bad_imu_pub_ = nh_.advertise<sensor_msgs::Imu>("/imu/data_raw", 10);
  }

  void onOdom(const nav_msgs::Odometry& odom) {
    const auto& p = odom.pose.pose;
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = Eigen::Vector3d(p.position.x, p.position.y, p.position.z);
    pose.linear() =
        Eigen::Quaterniond(p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z)
            .toRotationMatrix();
    poses_.push_back({odom.header.stamp, pose});
  }
  void onStatus(const vicc_msgs::TrackingStatus& status) { statuses_.push_back(status); }
  void onInfo(const sensor_msgs::CameraInfo& info) { last_info_ = info; }
  void onLog(const rosgraph_msgs::Log& log) {
    if (log.name == "/tracker" && log.level == rosgraph_msgs::Log::WARN)
      warnings_.push_back(log.msg);
  }

  /// Publishes `image` with the camera_info of the recording at `stamp`, so that the tracker
  /// gets the pair and its checks of the image run.
  void publishPaired(sensor_msgs::Image image, const ros::Time& stamp) {
    sensor_msgs::CameraInfo info = last_info_;
    image.header.stamp = info.header.stamp = stamp;
    bad_info_pub_.publish(info);
    bad_depth_pub_.publish(image);
  }

  /// Every few real frames, inject malformed input: the wrong encoding, the wrong size (each
  /// with its camera_info), a depth image and a camera_info 1 ms apart that pair with nothing,
  /// a NaN IMU reading and one far in the past.
  void onDepth(const ros::MessageEvent<sensor_msgs::Image const>& event) {
    if (event.getPublisherName() == ros::this_node::getName()) return;  // one we injected
    const sensor_msgs::Image& image = *event.getMessage();
    ++real_frames_;
    if (real_frames_ % 7 != 3 || last_info_.K[0] == 0.0) return;
    sensor_msgs::Image wrong_size;
    wrong_size.header = image.header;
    wrong_size.encoding = sensor_msgs::image_encodings::TYPE_32FC1;
    wrong_size.width = 8;
    wrong_size.height = 4;
    wrong_size.step = 8 * 4;
    wrong_size.data.assign(wrong_size.step * wrong_size.height, 0);
    publishPaired(wrong_size, image.header.stamp + ros::Duration(0.001));
    sensor_msgs::Image wrong_encoding = image;
    wrong_encoding.encoding = sensor_msgs::image_encodings::RGB8;
    publishPaired(wrong_encoding, image.header.stamp + ros::Duration(0.002));
    sensor_msgs::Image unpaired_depth = image;
    unpaired_depth.header.stamp += ros::Duration(0.003);
    sensor_msgs::CameraInfo unpaired_info = last_info_;
    unpaired_info.header.stamp = image.header.stamp + ros::Duration(0.004);
    bad_depth_pub_.publish(unpaired_depth);
    bad_info_pub_.publish(unpaired_info);
    unpaired_stamps_.insert(stampText(unpaired_depth.header.stamp));
    unpaired_stamps_.insert(stampText(unpaired_info.header.stamp));
    sensor_msgs::Imu nan_imu;
    nan_imu.header.stamp = image.header.stamp;
    nan_imu.header.frame_id = "imu_link";
    nan_imu.angular_velocity.x = std::numeric_limits<double>::quiet_NaN();
    bad_imu_pub_.publish(nan_imu);
    sensor_msgs::Imu old_imu;
    old_imu.header.stamp = image.header.stamp - ros::Duration(0.5);
    old_imu.header.frame_id = "imu_link";
    old_imu.linear_acceleration.z = 9.81;
    bad_imu_pub_.publish(old_imu);
    ++injected_;
  }

  ros::NodeHandle nh_;
  tf2_ros::Buffer buffer_{ros::Duration(60.0)};
  tf2_ros::TransformListener listener_;
  ros::Subscriber odom_sub_, status_sub_, info_sub_, depth_sub_, rosout_sub_;
  ros::Publisher bad_depth_pub_, bad_info_pub_, bad_imu_pub_;
  sensor_msgs::CameraInfo last_info_;
  std::set<std::string> unpaired_stamps_;  ///< of the injected depth and info that match nothing
  std::vector<std::string> warnings_;      ///< the tracker's, from /rosout
  std::vector<PoseSample> poses_;
  std::vector<vicc_msgs::TrackingStatus> statuses_;
  int real_frames_ = 0;
  int injected_ = 0;
};

TEST_F(TrackerNodeTest, FollowsGroundTruthDespiteBadAndUnpairedInput) {
  // short_test: 2 s still phase + ~4 s of motion at 15 Hz. Wait for the recording to end:
  // no new pose for 3 s after the last one (or the overall limit).
  vicc_test::waitForRecordingEnd([this] { return poses_.size(); });
  ASSERT_GT(injected_, 3) << "the bad-input injection did not run";
  ASSERT_GT(poses_.size(), 40u) << "too few tracked poses published";

  // Every published pose matches the ground truth at its stamp. The map was aligned to the
  // ground truth at the first tracked frame (~initial_pose_frame), so errors are drift.
  double max_position_error = 0.0;
  double max_rotation_error = 0.0;
  int compared = 0;
  for (const PoseSample& sample : poses_) {
    geometry_msgs::TransformStamped truth;
    try {
      truth = buffer_.lookupTransform("map", "pico_flexx_optical_frame_gt", sample.stamp);
    } catch (const std::exception& error) {
      continue;
    }
    const auto difference = vicc_tracking::poseDifference(
        vicc_tracking::isometryFromTransform(truth.transform), sample.pose);
    max_position_error = std::max(max_position_error, difference.translation);
    max_rotation_error = std::max(max_rotation_error, difference.rotation_deg);
    ++compared;
  }
  EXPECT_GT(compared, static_cast<int>(poses_.size()) * 9 / 10);
  EXPECT_LT(max_position_error, 0.02) << "metres";
  EXPECT_LT(max_rotation_error, 2.0) << "degrees";

  int lost = 0;
  int ok = 0;
  for (const auto& status : statuses_) {
    if (status.state == vicc_msgs::TrackingStatus::STATE_LOST) ++lost;
    if (status.state != vicc_msgs::TrackingStatus::STATE_OK) continue;
    ++ok;
    if (status.frame_index == 0) continue;  // the first frame starts the map, no ICP
    EXPECT_GT(status.iterations, 0u);
    EXPECT_GT(status.inlier_ratio, 0.3f);
    EXPECT_LT(status.residual_rms, 0.01f);
    EXPECT_EQ(status.init_strategy, "ekf");
  }
  EXPECT_EQ(lost, 0);
  EXPECT_EQ(ok, static_cast<int>(poses_.size()));
  // The real frames were paired with their camera_info despite the injections: (nearly) each
  // got a status (the 91 of short_test all do on a quiet machine).
  EXPECT_GE(statuses_.size() * 20, static_cast<size_t>(real_frames_) * 19)
      << statuses_.size() << " statuses for " << real_frames_ << " recorded depth frames";

  // The depth image and camera_info 1 ms apart: a warning on /rosout names an injected stamp
  // and both topics, and the node kept tracking (the checks above) and runs.
  std::string unpaired_warning;
  for (const std::string& warning : warnings_) {
    if (warning.find("same stamp") == std::string::npos) continue;
    for (const std::string& stamp : unpaired_stamps_)
      if (warning.find(stamp) != std::string::npos) unpaired_warning = warning;
  }
  EXPECT_FALSE(unpaired_warning.empty())
      << "no warning names an injected unpaired stamp; the tracker warned " << warnings_.size()
      << " times";
  EXPECT_NE(unpaired_warning.find("/pico_flexx/image_depth"), std::string::npos)
      << unpaired_warning;
  EXPECT_NE(unpaired_warning.find("/pico_flexx/camera_info"), std::string::npos)
      << unpaired_warning;
  EXPECT_TRUE(vicc_test::nodeIsRegistered("/tracker")) << "the tracker node ended";
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "tracker_rostest");
  return RUN_ALL_TESTS();
}
