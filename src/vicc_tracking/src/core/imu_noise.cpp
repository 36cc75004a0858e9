#include "vicc_tracking/imu_noise.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vicc_tracking {
namespace {

void requireAtLeast(double value, double minimum, bool strictly, const char* key) {
  const bool ok = std::isfinite(value) && (strictly ? value > minimum : value >= minimum);
  if (!ok) {
    throw std::invalid_argument(std::string(key) + (strictly ? " must be > 0" : " must be >= 0") +
                                " (missing or invalid: " + std::to_string(value) + ")");
  }
}

/// Variance of a sensor error over one sample of dt, for an interval of length T after a still
/// phase of length D: white noise density^2 dt, the residual bias of the still-phase average
/// (density^2 / D) integrated over T and spread over the T / dt samples, and the bias random
/// walk within the interval (walk^2 T^3 / 3, spread likewise).
double perSampleVariance(double density, double walk, double dt, double interval,
                         double still_duration) {
  const double white = density * density * dt;
  const double still_phase_bias = density * density / still_duration * interval * dt;
  const double bias_walk = walk * walk * interval * interval * dt / 3.0;
  return white + still_phase_bias + bias_walk;
}

}  // namespace

void ImuNoise::validate() const {
  requireAtLeast(accelerometer_noise_density, 0.0, true, "accelerometer_noise_density");
  requireAtLeast(accelerometer_random_walk, 0.0, false, "accelerometer_random_walk");
  requireAtLeast(gyroscope_noise_density, 0.0, true, "gyroscope_noise_density");
  requireAtLeast(gyroscope_random_walk, 0.0, false, "gyroscope_random_walk");
  requireAtLeast(update_rate, 0.0, true, "update_rate");
  requireAtLeast(accelerometer_turn_on_bias, 0.0, false, "accelerometer_turn_on_bias");
}

EkfConfig ekfNoiseFromImu(const EkfConfig& ekf, const ImuNoise& imu, double still_phase_duration) {
  imu.validate();
  ekf.validate();
  if (!(still_phase_duration > 0.0)) {
    throw std::invalid_argument("still_phase/duration must be > 0 to derive the IMU noise");
  }
  const double dt = 1.0 / imu.update_rate;
  const double interval = ekf.measurement_noise_reference_interval;
  EkfConfig derived = ekf;

  // The quaternion part of a small rotation theta is theta / 2: variances / 4.
  const double angle = perSampleVariance(imu.gyroscope_noise_density, imu.gyroscope_random_walk, dt,
                                         interval, still_phase_duration);
  derived.process_noise_rotation = angle / 4.0;
  // q_b is constant over an interval (Eq. 5.7): no more noise than the rotation.
  derived.process_noise_base = derived.process_noise_rotation;

  // The offset the still phase took for gravity is 2|b| off at most once the rig turned;
  // |b| = sqrt(3) b for a per-axis figure. Its velocity error (2|b| T)^2, spread over T / dt.
  const double offset_magnitude = std::sqrt(3.0) * imu.accelerometer_turn_on_bias;
  const double turned_offset = 4.0 * offset_magnitude * offset_magnitude * interval * dt;
  derived.process_noise_velocity =
      perSampleVariance(imu.accelerometer_noise_density, imu.accelerometer_random_walk, dt,
                        interval, still_phase_duration) +
      turned_offset;

  // White acceleration noise integrated twice over one sample: sigma_a^2 dt^3 / 3.
  const double accelerometer_position =
      imu.accelerometer_noise_density * imu.accelerometer_noise_density * dt * dt * dt / 3.0;
  derived.process_noise_position = std::max(ekf.process_noise_position, accelerometer_position);
  derived.validate();
  return derived;
}

}  // namespace vicc_tracking
