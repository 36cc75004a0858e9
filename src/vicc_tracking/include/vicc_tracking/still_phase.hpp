#pragma once
// Gyro bias and gravity from the still phase at the start of a recording (thesis 5.4.1).

#include <string>

#include "vicc_tracking/imu_types.hpp"

namespace vicc_tracking {

struct StillPhaseConfig {
  double duration = 1.0;       ///< seconds of IMU data to average
  double max_gyro_std = 0.05;  ///< rad/s; more means the rig moved
  double max_accel_std = 0.5;  ///< m/s^2
  void validate() const;
};

class StillPhaseCalibrator {
 public:
  explicit StillPhaseCalibrator(const StillPhaseConfig& config);

  /// Averages a reading; one with non-finite values or a stamp not after the last is ignored
  /// (returns false), so it cannot bias the estimate or stretch the phase.
  bool add(const ImuSample& sample);
  bool complete() const;
  /// Valid once complete().
  ImuCalibration calibration() const;
  /// Non-empty when the readings show the rig was not still (the estimate is then biased).
  std::string motionWarning() const;
  void reset();

 private:
  StillPhaseConfig config_;
  double first_stamp_ = 0.0;
  double last_stamp_ = 0.0;
  int count_ = 0;
  Eigen::Vector3d gyro_sum_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d gyro_sq_sum_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_sum_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_sq_sum_ = Eigen::Vector3d::Zero();
};

}  // namespace vicc_tracking
