#include <gtest/gtest.h>

#include <rosbag/bag.h>
#include <sensor_msgs/image_encodings.h>

#include "vicc_tracking/ros/conversions.hpp"
#include "vicc_tracking/ros/rig_bag.hpp"
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

TEST_F(RigMessagesTest, GrayImageIsMono16WithTheDepthsHeaderAndZeroWithoutDepth) {
  const RigImages images = rigImageMessages(rig_, 3, t0_);
  EXPECT_EQ(images.gray.encoding, sensor_msgs::image_encodings::MONO16);
  EXPECT_EQ(images.gray.header.stamp, images.depth.header.stamp);
  EXPECT_EQ(images.gray.header.frame_id, images.depth.header.frame_id);
  EXPECT_EQ(images.depth.data, rigDepthMessage(rig_, 3, t0_).data);
  const cv::Mat1f depth = depthImageView(images.depth);
  const cv::Mat1w gray = intensityImageView(images.gray);
  ASSERT_EQ(gray.size(), depth.size());
  int lit = 0, valid = 0;
  for (int v = 0; v < gray.rows; ++v) {
    for (int u = 0; u < gray.cols; ++u) {
      if (depth(v, u) <= 0.f) {
        EXPECT_EQ(gray(v, u), 0);
      } else {
        ++valid;
        lit += gray(v, u) > 0;
      }
    }
  }
  EXPECT_GT(lit, valid * 99 / 100);
  sensor_msgs::Image bad = images.gray;
  bad.encoding = "rgb8";
  EXPECT_THROW(intensityImageView(bad), std::invalid_argument);
  bad = images.gray;
  bad.data.resize(10);
  EXPECT_THROW(intensityImageView(bad), std::invalid_argument);
}

/// A bag with depth and gray: the depth topic is still found alone, the gray one too, and
/// frames get the gray image of their stamp in whichever order the two were recorded.
TEST_F(RigMessagesTest, RigBagFindsTheGrayTopicAndMatchesItByStamp) {
  const std::string path = ::testing::TempDir() + "vicc_gray_test.bag";
  {
    rosbag::Bag bag(path, rosbag::bagmode::Write);
    for (int k = 0; k < 4; ++k) {
      const ros::Time stamp = t0_ + ros::Duration(0.1 * k);
      const RigImages images = rigImageMessages(rig_, k, stamp);
      bag.write(RigTopics::kCameraInfo, stamp, rigCameraInfo(rig_, stamp));
      if (k == 1) bag.write(RigTopics::kGray, stamp, images.gray);  // gray first
      bag.write(RigTopics::kDepth, stamp, images.depth);
      if (k == 0 || k == 3) bag.write(RigTopics::kGray, stamp + ros::Duration(0.05), images.gray);
      // frame 2: no gray image
    }
  }
  const RigBag bag(path, {});
  EXPECT_EQ(bag.topics().depth, RigTopics::kDepth);
  EXPECT_EQ(bag.topics().intensity, RigTopics::kGray);
  std::vector<bool> with_gray;
  bag.forEachFrame([&](const sensor_msgs::ImageConstPtr& depth,
                       const sensor_msgs::CameraInfoConstPtr& info,
                       const sensor_msgs::ImageConstPtr& gray) {
    ASSERT_TRUE(info);
    if (gray) {
      EXPECT_EQ(gray->header.stamp, depth->header.stamp);
    }
    with_gray.push_back(static_cast<bool>(gray));
  });
  EXPECT_EQ(with_gray, (std::vector<bool>{true, true, false, true}));
  RigBagTopics no_gray;
  no_gray.intensity = RigBagTopics::kNone;
  const RigBag without(path, no_gray);
  EXPECT_TRUE(without.topics().intensity.empty());
  int frames = 0;
  without.forEachFrame([&](const sensor_msgs::ImageConstPtr&,
                           const sensor_msgs::CameraInfoConstPtr&,
                           const sensor_msgs::ImageConstPtr& gray) {
    EXPECT_FALSE(gray);
    ++frames;
  });
  EXPECT_EQ(frames, 4);
  RigBagTopics named;
  named.intensity = RigTopics::kDepth;
  EXPECT_THROW(RigBag(path, named), std::runtime_error);  // the depth itself
  named.intensity = "/no/such/topic";
  EXPECT_THROW(RigBag(path, named), std::runtime_error);
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
