#include <gtest/gtest.h>

#include <sensor_msgs/image_encodings.h>

#include "vicc_glyphs/ros/image_message.hpp"

namespace vicc_glyphs {
namespace {

TEST(ImageMessageTest, FloatImageBecomesRgb8) {
  cv::Mat image(3, 5, CV_32FC3, cv::Scalar(0, 0, 0));
  image.at<cv::Vec3f>(1, 2) = cv::Vec3f(1.0f, 0.5f, 0.0f);
  const sensor_msgs::Image message = toImageMsg(image, "glyph");
  EXPECT_EQ(message.encoding, sensor_msgs::image_encodings::RGB8);
  EXPECT_EQ(message.width, 5u);
  EXPECT_EQ(message.height, 3u);
  EXPECT_EQ(message.step, 15u);
  EXPECT_EQ(message.is_bigendian, 0);
  EXPECT_EQ(message.header.frame_id, "glyph");
  ASSERT_EQ(message.data.size(), 45u);
  const size_t pixel = 1 * 15 + 2 * 3;
  EXPECT_EQ(message.data[pixel], 255);  // red first: rgb8, not OpenCV's BGR
  EXPECT_EQ(message.data[pixel + 1], 128);
  EXPECT_EQ(message.data[pixel + 2], 0);
}

TEST(ImageMessageTest, ByteImagePassesThroughAndOtherTypesAreRejected) {
  cv::Mat bytes(2, 2, CV_8UC3, cv::Scalar(10, 20, 30));
  EXPECT_EQ(toImageMsg(bytes).data[2], 30);
  EXPECT_THROW(toImageMsg(cv::Mat(2, 2, CV_8UC1)), std::invalid_argument);
}

}  // namespace
}  // namespace vicc_glyphs
