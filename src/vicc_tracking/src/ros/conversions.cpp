#include "vicc_tracking/ros/conversions.hpp"

#include <cmath>
#include <cstring>
#include <sstream>
#include <stdexcept>

#include <sensor_msgs/image_encodings.h>

namespace vicc_tracking {
namespace {

bool allFinite(const geometry_msgs::Vector3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

CameraModel cameraModelFromInfo(const sensor_msgs::CameraInfo& info) {
  CameraModel camera;
  camera.width = static_cast<int>(info.width);
  camera.height = static_cast<int>(info.height);
  camera.fx = info.K[0];
  camera.fy = info.K[4];
  camera.cx = info.K[2];
  camera.cy = info.K[5];
  camera.model = distortionModelFromString(info.distortion_model);
  camera.distortion = info.D;
  if (info.binning_x > 1 || info.binning_y > 1) {
    throw std::invalid_argument("camera_info: binning is not supported");
  }
  camera.validate();
  return camera;
}

sensor_msgs::CameraInfo cameraInfoFromModel(const CameraModel& camera) {
  sensor_msgs::CameraInfo info;
  info.width = static_cast<uint32_t>(camera.width);
  info.height = static_cast<uint32_t>(camera.height);
  info.distortion_model = toString(camera.model);
  info.D = camera.distortion;
  info.K = {camera.fx, 0.0, camera.cx, 0.0, camera.fy, camera.cy, 0.0, 0.0, 1.0};
  info.R = {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};
  info.P = {camera.fx, 0.0, camera.cx, 0.0, 0.0, camera.fy, camera.cy, 0.0, 0.0, 0.0, 1.0, 0.0};
  return info;
}

namespace {

/// A cv::Mat over the message's data after checking size, step and byte order; `what` names
/// the image in the error messages.
cv::Mat checkedView(const sensor_msgs::Image& image, int type, size_t element_size,
                    const std::string& what) {
  if (image.width == 0 || image.height == 0) {
    throw std::invalid_argument(what + " image is empty (0 width or height)");
  }
  if (image.step < image.width * element_size ||
      image.data.size() < static_cast<size_t>(image.step) * image.height) {
    std::ostringstream message;
    message << what << " image " << image.width << "x" << image.height << " has step " << image.step
            << " and " << image.data.size() << " bytes of data: too small";
    throw std::invalid_argument(message.str());
  }
  const bool host_big_endian = false;  // x86/ARM Linux hosts are little endian
  if (element_size > 1 && static_cast<bool>(image.is_bigendian) != host_big_endian) {
    throw std::invalid_argument(what + " image is big-endian; only little-endian is supported");
  }
  // The Mat is read-only in practice; OpenCV's API needs a non-const pointer.
  return cv::Mat(static_cast<int>(image.height), static_cast<int>(image.width), type,
                 const_cast<uint8_t*>(image.data.data()), image.step);
}

}  // namespace

cv::Mat depthImageView(const sensor_msgs::Image& image) {
  namespace enc = sensor_msgs::image_encodings;
  if (image.encoding == enc::TYPE_32FC1) return checkedView(image, CV_32FC1, 4, "depth");
  if (image.encoding == enc::TYPE_16UC1 || image.encoding == enc::MONO16) {
    return checkedView(image, CV_16UC1, 2, "depth");
  }
  throw std::invalid_argument("depth image has encoding '" + image.encoding +
                              "'; expected 32FC1 (metres) or 16UC1 (millimetres)");
}

cv::Mat intensityImageView(const sensor_msgs::Image& image) {
  namespace enc = sensor_msgs::image_encodings;
  if (image.encoding == enc::MONO8 || image.encoding == enc::TYPE_8UC1) {
    return checkedView(image, CV_8UC1, 1, "gray");
  }
  if (image.encoding == enc::MONO16 || image.encoding == enc::TYPE_16UC1) {
    return checkedView(image, CV_16UC1, 2, "gray");
  }
  if (image.encoding == enc::TYPE_32FC1) return checkedView(image, CV_32FC1, 4, "gray");
  throw std::invalid_argument("gray image has encoding '" + image.encoding +
                              "'; expected mono8, mono16 or 32FC1");
}

bool isGrayEncoding(const std::string& encoding) {
  return encoding == sensor_msgs::image_encodings::MONO8 ||
         encoding == sensor_msgs::image_encodings::MONO16;
}

namespace {

/// A little-endian Image message holding a copy of `mat` (rows packed).
sensor_msgs::Image imageMessage(const cv::Mat& mat, const std::string& encoding) {
  sensor_msgs::Image image;
  image.encoding = encoding;
  image.width = static_cast<uint32_t>(mat.cols);
  image.height = static_cast<uint32_t>(mat.rows);
  image.step = static_cast<uint32_t>(image.width * mat.elemSize());
  image.is_bigendian = 0;
  image.data.resize(static_cast<size_t>(image.step) * image.height);
  for (int row = 0; row < mat.rows; ++row) {
    std::memcpy(&image.data[static_cast<size_t>(row) * image.step], mat.ptr(row), image.step);
  }
  return image;
}

}  // namespace

sensor_msgs::Image mono16ImageMessage(const cv::Mat& gray) {
  if (gray.type() != CV_16UC1) throw std::invalid_argument("mono16ImageMessage expects CV_16UC1");
  return imageMessage(gray, sensor_msgs::image_encodings::MONO16);
}

sensor_msgs::Image depthImageMessage(const cv::Mat& depth_metres) {
  if (depth_metres.type() != CV_32FC1) {
    throw std::invalid_argument("depthImageMessage expects a CV_32FC1 image");
  }
  return imageMessage(depth_metres, sensor_msgs::image_encodings::TYPE_32FC1);
}

ImuSample imuSampleFromMessage(const sensor_msgs::Imu& imu) {
  if (imu.header.stamp.isZero()) {
    throw std::invalid_argument("IMU message has a zero stamp");
  }
  if (!allFinite(imu.angular_velocity) || !allFinite(imu.linear_acceleration)) {
    throw std::invalid_argument("IMU message contains NaN or Inf");
  }
  ImuSample sample;
  sample.stamp = imu.header.stamp.toSec();
  sample.angular_velocity =
      Eigen::Vector3d(imu.angular_velocity.x, imu.angular_velocity.y, imu.angular_velocity.z);
  sample.linear_acceleration = Eigen::Vector3d(imu.linear_acceleration.x, imu.linear_acceleration.y,
                                               imu.linear_acceleration.z);
  return sample;
}

Eigen::Isometry3d isometryFromTransform(const geometry_msgs::Transform& transform) {
  const auto& r = transform.rotation;
  Eigen::Quaterniond rotation(r.w, r.x, r.y, r.z);
  if (!std::isfinite(rotation.norm()) || std::abs(rotation.norm() - 1.0) > 1e-3) {
    throw std::invalid_argument("transform has a non-unit rotation quaternion");
  }
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = rotation.normalized().toRotationMatrix();
  pose.translation() =
      Eigen::Vector3d(transform.translation.x, transform.translation.y, transform.translation.z);
  return pose;
}

geometry_msgs::Transform transformFromIsometry(const Eigen::Isometry3d& pose) {
  geometry_msgs::Transform transform;
  const Eigen::Quaterniond rotation(pose.linear());
  transform.translation.x = pose.translation().x();
  transform.translation.y = pose.translation().y();
  transform.translation.z = pose.translation().z();
  transform.rotation.w = rotation.w();
  transform.rotation.x = rotation.x();
  transform.rotation.y = rotation.y();
  transform.rotation.z = rotation.z();
  return transform;
}

geometry_msgs::Pose poseFromIsometry(const Eigen::Isometry3d& pose) {
  const geometry_msgs::Transform transform = transformFromIsometry(pose);
  geometry_msgs::Pose result;
  result.position.x = transform.translation.x;
  result.position.y = transform.translation.y;
  result.position.z = transform.translation.z;
  result.orientation = transform.rotation;
  return result;
}

}  // namespace vicc_tracking
