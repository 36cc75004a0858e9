#include "vicc_tracking/ros/conversions.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include <cv_bridge/cv_bridge.h>
#include <geometry_msgs/TransformStamped.h>
#include <sensor_msgs/image_encodings.h>
#include <tf2_eigen/tf2_eigen.h>

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

/// The message's pixels as a cv::Mat of `type` over the message's data (cv_bridge, no copy).
/// `what` names the image in the error messages.
cv::Mat sharedView(const sensor_msgs::Image& image, int type, const std::string& what) {
  if (image.width == 0 || image.height == 0) {
    throw std::invalid_argument(what + " image is empty (0 width or height)");
  }
  // cv_bridge's byte swap of big-endian images returns the bytes as CV_8UC2/CV_8UC4 instead of
  // the pixel type (Debian's cv_bridge 1.16): refused here rather than passed on as depth.
  const bool host_big_endian = false;  // x86/ARM Linux hosts are little endian
  if (CV_ELEM_SIZE1(type) > 1 && static_cast<bool>(image.is_bigendian) != host_big_endian) {
    throw std::invalid_argument(what + " image is big-endian; only little-endian is supported");
  }
  try {
    cv::Mat view = cv_bridge::toCvShare(image, nullptr, image.encoding)->image;
    if (view.type() != type) {
      throw std::invalid_argument(what + " image (" + image.encoding +
                                  ") did not convert to the expected pixel type");
    }
    return view;
  } catch (const cv_bridge::Exception& error) {
    std::ostringstream message;
    message << what << " image " << image.width << "x" << image.height << " (" << image.encoding
            << ", step " << image.step << ", " << image.data.size() << " bytes): " << error.what();
    throw std::invalid_argument(message.str());
  }
}

}  // namespace

cv::Mat depthImageView(const sensor_msgs::Image& image) {
  namespace enc = sensor_msgs::image_encodings;
  if (image.encoding == enc::TYPE_32FC1 || image.encoding == enc::TYPE_16UC1 ||
      image.encoding == enc::MONO16) {
    return sharedView(image, image.encoding == enc::TYPE_32FC1 ? CV_32FC1 : CV_16UC1, "depth");
  }
  throw std::invalid_argument("depth image has encoding '" + image.encoding +
                              "'; expected 32FC1 (metres) or 16UC1 (millimetres)");
}

cv::Mat intensityImageView(const sensor_msgs::Image& image) {
  namespace enc = sensor_msgs::image_encodings;
  if (image.encoding == enc::MONO8 || image.encoding == enc::TYPE_8UC1) {
    return sharedView(image, CV_8UC1, "gray");
  }
  if (image.encoding == enc::MONO16 || image.encoding == enc::TYPE_16UC1) {
    return sharedView(image, CV_16UC1, "gray");
  }
  if (image.encoding == enc::TYPE_32FC1) return sharedView(image, CV_32FC1, "gray");
  throw std::invalid_argument("gray image has encoding '" + image.encoding +
                              "'; expected mono8, mono16 or 32FC1");
}

bool isGrayEncoding(const std::string& encoding) {
  return encoding == sensor_msgs::image_encodings::MONO8 ||
         encoding == sensor_msgs::image_encodings::MONO16;
}

namespace {

/// An Image message holding a copy of `mat` (rows packed, host byte order).
sensor_msgs::Image imageMessage(const cv::Mat& mat, const std::string& encoding) {
  sensor_msgs::Image image;
  cv_bridge::CvImage(std_msgs::Header(), encoding, mat).toImageMsg(image);
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
  const double norm = std::sqrt(r.w * r.w + r.x * r.x + r.y * r.y + r.z * r.z);
  if (!std::isfinite(norm) || std::abs(norm - 1.0) > 1e-3) {
    throw std::invalid_argument("transform has a non-unit rotation quaternion");
  }
  // tf2_eigen takes the quaternion as it is: normalise it so the rotation is orthonormal.
  geometry_msgs::TransformStamped stamped;
  stamped.transform = transform;
  stamped.transform.rotation.w /= norm;
  stamped.transform.rotation.x /= norm;
  stamped.transform.rotation.y /= norm;
  stamped.transform.rotation.z /= norm;
  return tf2::transformToEigen(stamped);
}

geometry_msgs::Transform transformFromIsometry(const Eigen::Isometry3d& pose) {
  return tf2::eigenToTransform(pose).transform;
}

geometry_msgs::Pose poseFromIsometry(const Eigen::Isometry3d& pose) { return tf2::toMsg(pose); }

}  // namespace vicc_tracking
