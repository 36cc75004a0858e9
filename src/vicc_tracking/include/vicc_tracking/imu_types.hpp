#pragma once
#include <Eigen/Core>

namespace vicc_tracking {

/// One raw IMU reading (REP-145): angular velocity in rad/s and specific force incl.
/// gravity in m/s^2, both in the IMU frame.
struct ImuSample {
  double stamp = 0.0;
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d linear_acceleration = Eigen::Vector3d::Zero();
};

/// One integration step: the reading held constant over dt seconds.
struct ImuStep {
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d linear_acceleration = Eigen::Vector3d::Zero();
  double dt = 0.0;
};

/// Sensor errors estimated in the still phase (thesis 5.4.1).
struct ImuCalibration {
  Eigen::Vector3d gyro_bias = Eigen::Vector3d::Zero();
  /// Mean specific force at rest in the IMU frame: gravity plus the accelerometer bias,
  /// i.e. g~ of the thesis before it is rotated into the reference frame.
  Eigen::Vector3d gravity_imu = Eigen::Vector3d(0.0, 0.0, 9.80665);
};

}  // namespace vicc_tracking
