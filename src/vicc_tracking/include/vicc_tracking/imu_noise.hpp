#pragma once
// IMU noise as datasheets and Allan-variance calibrations state it, in the layout of Kalibr's
// imu.yaml (and of the VIO tools that read it), and the EKF process noise derived from it.
// The derivation is docs/imu_noise.md; the file reader is tracker_config_yaml.hpp.

#include <string>

#include "vicc_tracking/ekf.hpp"

namespace vicc_tracking {

struct ImuNoise {
  double accelerometer_noise_density = 0.0;  ///< sigma_a, m/s^2/sqrt(Hz) (white noise)
  double accelerometer_random_walk = 0.0;    ///< sigma_ba, m/s^3/sqrt(Hz) (bias diffusion)
  double gyroscope_noise_density = 0.0;      ///< sigma_g, rad/s/sqrt(Hz)
  double gyroscope_random_walk = 0.0;        ///< sigma_bg, rad/s^2/sqrt(Hz)
  double update_rate = 0.0;                  ///< Hz
  std::string rostopic;                      ///< Kalibr's topic entry; recorded, not used
  /// Extension to Kalibr's layout: per-axis accelerometer offset left after the factory
  /// calibration (datasheet "zero-g offset"), m/s^2. The still phase folds it into gravity at
  /// the start attitude only, so it returns as a velocity error once the rig turns.
  double accelerometer_turn_on_bias = 0.0;

  /// Throws std::invalid_argument naming the key: densities and rate > 0, the rest >= 0.
  void validate() const;
};

/// ekf with Q (per IMU sample) replaced by the values derived from the IMU's noise
/// (docs/imu_noise.md). Q_p keeps the larger of the configured value (the Euler term of
/// p' = p + dt v, a property of the motion) and the accelerometer's share, so applying it twice
/// changes nothing. R and P0 stay: they describe the extrapolation and the ICP, not the IMU.
/// still_phase_duration: seconds averaged for the gyro bias and gravity (still_phase.duration).
EkfConfig ekfNoiseFromImu(const EkfConfig& ekf, const ImuNoise& imu, double still_phase_duration);

}  // namespace vicc_tracking
