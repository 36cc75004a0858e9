#include <gtest/gtest.h>

#include <sensor_msgs/image_encodings.h>

#include "vicc_tracking/ros/conversions.hpp"
#include "vicc_tracking/ros/rig_messages.hpp"

using namespace vicc_tracking;

namespace {

class RigMessagesTest : public ::testing::Test {
 protected:
  RigMessagesTest() : rig_(sim::loadScenario("short_test")) {}
  sim::RigSimulator rig_;
  const ros::Time t0_{1700000000.0};
};

TEST_F(RigMessagesTest, ImuIsRep145RawData) {
  const sensor_msgs::Imu imu = rigImuMessage(rig_, 0, t0_);
  EXPECT_EQ(imu.header.frame_id, "imu_link");
  EXPECT_EQ(imu.header.stamp, t0_);
  EXPECT_EQ(imu.orientation_covariance[0], -1.0);
  // At rest the accelerometer reads gravity's reaction, 9.81 m/s^2 (plus bias and noise).
  const Eigen::Vector3d specific_force(imu.linear_acceleration.x, imu.linear_acceleration.y,
                                       imu.linear_acceleration.z);
  EXPECT_NEAR(specific_force.norm(), 9.80665, 0.2);
  EXPECT_LT(std::abs(imu.angular_velocity.x), 0.05);
  EXPECT_GT(imu.angular_velocity_covariance[0], 0.0);
}

TEST_F(RigMessagesTest, ExtrinsicIsARealRotation) {
  const geometry_msgs::TransformStamped extrinsic = rigExtrinsic(rig_, t0_);
  EXPECT_EQ(extrinsic.header.frame_id, "imu_link");
  EXPECT_EQ(extrinsic.child_frame_id, "pico_flexx_optical_frame");
  const Eigen::Isometry3d pose = isometryFromTransform(extrinsic.transform);
  const Eigen::AngleAxisd rotation(pose.linear());
  EXPECT_GT(rotation.angle(), 0.5);  // optical z is not the IMU's z
}

TEST_F(RigMessagesTest, DepthAndCameraInfoMatchThePicoFlexx) {
  const sensor_msgs::Image depth = rigDepthMessage(rig_, 0, t0_);
  const sensor_msgs::CameraInfo info = rigCameraInfo(rig_, t0_);
  EXPECT_EQ(depth.encoding, sensor_msgs::image_encodings::TYPE_32FC1);
  EXPECT_EQ(depth.width, 224u);
  EXPECT_EQ(depth.height, 171u);
  EXPECT_EQ(depth.header.frame_id, "pico_flexx_optical_frame");
  EXPECT_EQ(info.header.frame_id, depth.header.frame_id);
  EXPECT_EQ(info.distortion_model, "plumb_bob");
  EXPECT_NO_THROW(cameraModelFromInfo(info));
  const cv::Mat view = depthImageView(depth);
  int valid = 0;
  for (int v = 0; v < view.rows; ++v) {
    for (int u = 0; u < view.cols; ++u) valid += view.at<float>(v, u) > 0.f;
  }
  EXPECT_GT(valid, view.rows * view.cols / 2) << "the scene should fill most of the view";
}

TEST_F(RigMessagesTest, GroundTruthIsTheSimulatorPose) {
  const double t = rig_.duration() * 0.6;
  const geometry_msgs::TransformStamped truth = rigGroundTruth(rig_, t, t0_);
  EXPECT_EQ(truth.header.frame_id, "map");
  EXPECT_EQ(truth.child_frame_id, "pico_flexx_optical_frame_gt");
  const Eigen::Isometry3d pose = isometryFromTransform(truth.transform);
  EXPECT_LT((pose.matrix() - rig_.cameraPose(t).matrix()).norm(), 1e-9);
}

}  // namespace
