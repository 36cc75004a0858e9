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

// cv_bridge's byte swap returns the bytes, not 16-bit pixels: refused, never passed on.
TEST(ConversionsTest, BigEndianDepthIsRejected) {
  sensor_msgs::Image image;
  image.width = 2;
  image.height = 1;
  image.encoding = sensor_msgs::image_encodings::TYPE_16UC1;
  image.is_bigendian = 1;
  image.step = 4;
  image.data = {0x01, 0x02, 0x03, 0x04};
  try {
    depthImageView(image);
    FAIL() << "a big-endian depth image was accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("big-endian"), std::string::npos) << error.what();
  }
  // One byte per pixel has no byte order.
  image.encoding = sensor_msgs::image_encodings::MONO8;
  image.width = 4;
  EXPECT_EQ(intensityImageView(image).type(), CV_8UC1);
}

TEST(ConversionsTest, MalformedImagesAreRejectedNamingTheImage) {
  sensor_msgs::Image image;
  image.width = 4;
  image.height = 2;
  image.encoding = sensor_msgs::image_encodings::MONO16;
  image.step = 8;
  image.data.assign(12, 0);  // 2 rows of 8 bytes need 16
  try {
    intensityImageView(image);
    FAIL() << "a short gray image was accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("gray image 4x2 (mono16"), std::string::npos)
        << error.what();
  }
  image.data.assign(16, 0);
  EXPECT_EQ(intensityImageView(image).type(), CV_16UC1);
  image.width = 0;
  EXPECT_THROW(intensityImageView(image), std::invalid_argument);
  image.width = 4;
  image.encoding = sensor_msgs::image_encodings::BGR8;
  try {
    intensityImageView(image);
    FAIL() << "a colour image was accepted as gray";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("'bgr8'"), std::string::npos) << error.what();
  }
}

TEST(ConversionsTest, Mono16MessageKeepsValuesAndPacksRows) {
  cv::Mat1w gray(2, 3, static_cast<uint16_t>(7));
  gray(1, 2) = 65535;
  const cv::Mat1w roi = gray(cv::Rect(1, 0, 2, 2));  // not continuous: rows must be packed
  const sensor_msgs::Image message = mono16ImageMessage(roi);
  EXPECT_EQ(message.encoding, sensor_msgs::image_encodings::MONO16);
  EXPECT_EQ(message.step, 4u);
  ASSERT_EQ(message.data.size(), 8u);
  EXPECT_EQ(intensityImageView(message).at<uint16_t>(1, 1), 65535);
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

TEST(ConversionsTest, NearlyUnitQuaternionGivesAnOrthonormalRotationAndPoseMatches) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(-1.1, Eigen::Vector3d(0, 1, 1).normalized()).toRotationMatrix();
  pose.translation() = Eigen::Vector3d(1.5, 0.25, -2.0);
  geometry_msgs::Transform scaled = transformFromIsometry(pose);
  for (double* q :
       {&scaled.rotation.w, &scaled.rotation.x, &scaled.rotation.y, &scaled.rotation.z}) {
    *q *= 1.0005;  // within the 1e-3 tolerance
  }
  const Eigen::Isometry3d back = isometryFromTransform(scaled);
  EXPECT_LT((back.linear() * back.linear().transpose() - Eigen::Matrix3d::Identity()).norm(),
            1e-12);
  EXPECT_LT((back.matrix() - pose.matrix()).norm(), 1e-12);
  const geometry_msgs::Pose message = poseFromIsometry(pose);
  EXPECT_DOUBLE_EQ(message.position.x, 1.5);
  EXPECT_DOUBLE_EQ(message.position.z, -2.0);
  const Eigen::Quaterniond q(pose.linear());
  EXPECT_NEAR(std::abs(message.orientation.w * q.w() + message.orientation.x * q.x() +
                       message.orientation.y * q.y() + message.orientation.z * q.z()),
              1.0, 1e-12);
}

}  // namespace
