#include "vicc_glyphs/ros/image_message.hpp"

#include <sensor_msgs/image_encodings.h>

#include <stdexcept>

#include "vicc_glyphs/render/png_output.hpp"

namespace vicc_glyphs {

sensor_msgs::Image toImageMsg(const cv::Mat& rgb, const std::string& frame_id) {
  cv::Mat bytes;
  if (rgb.type() == CV_32FC3) {
    bytes = toRgb8(rgb);
  } else if (rgb.type() == CV_8UC3) {
    bytes = rgb;
  } else {
    throw std::invalid_argument("toImageMsg: expects CV_32FC3 or CV_8UC3 RGB");
  }
  sensor_msgs::Image message;
  message.header.frame_id = frame_id;
  message.height = static_cast<std::uint32_t>(bytes.rows);
  message.width = static_cast<std::uint32_t>(bytes.cols);
  message.encoding = sensor_msgs::image_encodings::RGB8;
  message.is_bigendian = 0;
  message.step = static_cast<std::uint32_t>(3 * bytes.cols);
  message.data.resize(static_cast<size_t>(message.step) * bytes.rows);
  for (int y = 0; y < bytes.rows; ++y) {
    const std::uint8_t* row = bytes.ptr<std::uint8_t>(y);
    std::copy(row, row + message.step, message.data.begin() + static_cast<long>(y) * message.step);
  }
  return message;
}

}  // namespace vicc_glyphs
