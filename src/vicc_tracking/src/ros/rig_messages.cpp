#include "vicc_tracking/ros/rig_messages.hpp"

#include "vicc_tracking/ros/conversions.hpp"

namespace vicc_tracking {

sensor_msgs::Image rigDepthMessage(const sim::RigSimulator& rig, int frame_index,
                                   const ros::Time& stamp) {
  sensor_msgs::Image image = depthImageMessage(rig.renderDepth(frame_index));
  image.header.stamp = stamp;
  image.header.frame_id = rig.scenario().frame_camera;
  return image;
}

RigImages rigImageMessages(const sim::RigSimulator& rig, int frame_index, const ros::Time& stamp) {
  const sim::RigSimulator::Frame frame = rig.renderFrame(frame_index);
  RigImages images;
  images.depth = depthImageMessage(frame.depth);
  images.depth.header.stamp = stamp;
  images.depth.header.frame_id = rig.scenario().frame_camera;
  images.gray = mono16ImageMessage(frame.amplitude);
  images.gray.header = images.depth.header;
  return images;
}

sensor_msgs::CameraInfo rigCameraInfo(const sim::RigSimulator& rig, const ros::Time& stamp) {
  sensor_msgs::CameraInfo info = cameraInfoFromModel(rig.scenario().camera);
  info.header.stamp = stamp;
  info.header.frame_id = rig.scenario().frame_camera;
  return info;
}

sensor_msgs::Imu rigImuMessage(const sim::RigSimulator& rig, int sample_index,
                               const ros::Time& stamp) {
  const ImuSample sample = rig.imuSample(sample_index);
  const sim::ImuNoiseConfig& noise = rig.scenario().imu;
  sensor_msgs::Imu imu;
  imu.header.stamp = stamp;
  imu.header.frame_id = rig.scenario().frame_imu;
  imu.orientation_covariance[0] = -1.0;  // REP-145 raw data: no orientation estimate
  imu.angular_velocity.x = sample.angular_velocity.x();
  imu.angular_velocity.y = sample.angular_velocity.y();
  imu.angular_velocity.z = sample.angular_velocity.z();
  imu.linear_acceleration.x = sample.linear_acceleration.x();
  imu.linear_acceleration.y = sample.linear_acceleration.y();
  imu.linear_acceleration.z = sample.linear_acceleration.z();
  // White-noise variance per reading: density^2 * rate.
  const double gyro_variance = noise.gyro_noise_density * noise.gyro_noise_density * noise.rate_hz;
  const double accel_variance =
      noise.accel_noise_density * noise.accel_noise_density * noise.rate_hz;
  for (int i = 0; i < 3; ++i) {
    imu.angular_velocity_covariance[i * 4] = gyro_variance;
    imu.linear_acceleration_covariance[i * 4] = accel_variance;
  }
  return imu;
}

geometry_msgs::TransformStamped rigExtrinsic(const sim::RigSimulator& rig, const ros::Time& stamp) {
  geometry_msgs::TransformStamped transform;
  transform.header.stamp = stamp;
  transform.header.frame_id = rig.scenario().frame_imu;
  transform.child_frame_id = rig.scenario().frame_camera;
  transform.transform = transformFromIsometry(rig.scenario().imu_to_camera);
  return transform;
}

std::string groundTruthFrame(const sim::Scenario& scenario) {
  return scenario.frame_camera + "_gt";
}

geometry_msgs::TransformStamped rigGroundTruth(const sim::RigSimulator& rig, double t,
                                               const ros::Time& stamp) {
  geometry_msgs::TransformStamped transform;
  transform.header.stamp = stamp;
  transform.header.frame_id = rig.scenario().frame_map;
  transform.child_frame_id = groundTruthFrame(rig.scenario());
  transform.transform = transformFromIsometry(rig.cameraPose(t));
  return transform;
}

}  // namespace vicc_tracking
