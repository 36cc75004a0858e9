#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <sensor_msgs/image_encodings.h>

#include "vicc_tracking/ros/conversions.hpp"
#include "vicc_tracking/sim/scenario.hpp"

using namespace vicc_tracking;

namespace {

CameraModel picoFlexx() { return sim::picoFlexxCamera(); }

TEST(ConversionsTest, CameraInfoRoundTrip) {
  const CameraModel camera = picoFlexx();
  const CameraModel back = cameraModelFromInfo(cameraInfoFromModel(camera));
  EXPECT_EQ(back.width, 224);
  EXPECT_EQ(back.height, 171);
  EXPECT_DOUBLE_EQ(back.fx, 210.0);
  EXPECT_DOUBLE_EQ(back.cy, 85.5);
  EXPECT_EQ(back.model, DistortionModel::kPlumbBob);
  EXPECT_EQ(back.distortion, camera.distortion);
}

TEST(ConversionsTest, InvalidCameraInfoIsRejectedWithReason) {
  sensor_msgs::CameraInfo info = cameraInfoFromModel(picoFlexx());
  info.K[0] = 0.0;
  EXPECT_THROW(cameraModelFromInfo(info), std::invalid_argument);
  info = cameraInfoFromModel(picoFlexx());
  info.distortion_model = "rational_polynomial";
  EXPECT_THROW(cameraModelFromInfo(info), std::invalid_argument);
  info = cameraInfoFromModel(picoFlexx());
  info.width = 0;
  EXPECT_THROW(cameraModelFromInfo(info), std::invalid_argument);
}

TEST(ConversionsTest, DepthViewSharesDataAndKeepsValues) {
  cv::Mat1f depth(3, 4, 0.5f);
  depth(1, 2) = 1.25f;
  const sensor_msgs::Image message = depthImageMessage(depth);
  EXPECT_EQ(message.encoding, sensor_msgs::image_encodings::TYPE_32FC1);
  const cv::Mat view = depthImageView(message);
  ASSERT_EQ(view.type(), CV_32FC1);
  EXPECT_FLOAT_EQ(view.at<float>(1, 2), 1.25f);
  EXPECT_EQ(view.data, message.data.data());  // no copy
}

TEST(ConversionsTest, DepthViewAcceptsMillimetresAndRejectsOtherEncodings) {
  sensor_msgs::Image image;
  image.width = 2;
  image.height = 2;
  image.encoding = sensor_msgs::image_encodings::TYPE_16UC1;
  image.step = 4;
  image.data.assign(8, 0);
  EXPECT_EQ(depthImageView(image).type(), CV_16UC1);
  image.encoding = sensor_msgs::image_encodings::RGB8;
  EXPECT_THROW(depthImageView(image), std::invalid_argument);
  image.encoding = sensor_msgs::image_encodings::TYPE_32FC1;  // 2x2 floats need 16 bytes
  EXPECT_THROW(depthImageView(image), std::invalid_argument);
}

TEST(ConversionsTest, ImuRejectsNanAndZeroStamp) {
  sensor_msgs::Imu imu;
  imu.header.stamp = ros::Time(10.0);
  imu.linear_acceleration.z = 9.81;
  imu.angular_velocity.x = 0.1;
  const ImuSample sample = imuSampleFromMessage(imu);
  EXPECT_DOUBLE_EQ(sample.stamp, 10.0);
  EXPECT_DOUBLE_EQ(sample.linear_acceleration.z(), 9.81);
  EXPECT_DOUBLE_EQ(sample.angular_velocity.x(), 0.1);
  imu.angular_velocity.y = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(imuSampleFromMessage(imu), std::invalid_argument);
  imu.angular_velocity.y = 0.0;
  imu.header.stamp = ros::Time(0.0);
  EXPECT_THROW(imuSampleFromMessage(imu), std::invalid_argument);
}

TEST(ConversionsTest, TransformRoundTripAndNonUnitQuaternion) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  pose.translation() = Eigen::Vector3d(0.1, -0.2, 0.3);
  const Eigen::Isometry3d back = isometryFromTransform(transformFromIsometry(pose));
  EXPECT_LT((back.matrix() - pose.matrix()).norm(), 1e-12);
  geometry_msgs::Transform bad = transformFromIsometry(pose);
  bad.rotation.w = 2.0;
  EXPECT_THROW(isometryFromTransform(bad), std::invalid_argument);
}

}  // namespace
