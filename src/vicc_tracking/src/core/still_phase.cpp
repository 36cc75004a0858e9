#include "vicc_tracking/still_phase.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace vicc_tracking {

void StillPhaseConfig::validate() const {
  if (!(duration > 0.0) || !std::isfinite(duration)) {
    throw std::invalid_argument("still_phase.duration must be > 0 s");
  }
  if (!(max_gyro_std > 0.0) || !(max_accel_std > 0.0)) {
    throw std::invalid_argument("still_phase.max_gyro_std and max_accel_std must be > 0");
  }
}

StillPhaseCalibrator::StillPhaseCalibrator(const StillPhaseConfig& config) : config_(config) {
  config_.validate();
}

bool StillPhaseCalibrator::add(const ImuSample& sample) {
  if (!std::isfinite(sample.stamp) || !sample.angular_velocity.allFinite() ||
      !sample.linear_acceleration.allFinite() || (count_ > 0 && !(sample.stamp > last_stamp_))) {
    return false;
  }
  if (count_ == 0) first_stamp_ = sample.stamp;
  last_stamp_ = sample.stamp;
  ++count_;
  gyro_sum_ += sample.angular_velocity;
  gyro_sq_sum_ += sample.angular_velocity.cwiseAbs2();
  accel_sum_ += sample.linear_acceleration;
  accel_sq_sum_ += sample.linear_acceleration.cwiseAbs2();
  return true;
}

bool StillPhaseCalibrator::complete() const {
  return count_ >= 10 && last_stamp_ - first_stamp_ >= config_.duration;
}

ImuCalibration StillPhaseCalibrator::calibration() const {
  ImuCalibration calibration;
  if (count_ == 0) return calibration;
  calibration.gyro_bias = gyro_sum_ / count_;
  calibration.gravity_imu = accel_sum_ / count_;
  return calibration;
}

std::string StillPhaseCalibrator::motionWarning() const {
  if (count_ < 2) return "";
  auto max_std = [this](const Eigen::Vector3d& sum, const Eigen::Vector3d& sq_sum) {
    const Eigen::Vector3d mean = sum / count_;
    const Eigen::Vector3d variance = (sq_sum / count_ - mean.cwiseAbs2()).cwiseMax(0.0);
    return std::sqrt(variance.maxCoeff());
  };
  const double gyro_std = max_std(gyro_sum_, gyro_sq_sum_);
  const double accel_std = max_std(accel_sum_, accel_sq_sum_);
  std::ostringstream out;
  if (gyro_std > config_.max_gyro_std) {
    out << "gyro std " << gyro_std << " rad/s exceeds " << config_.max_gyro_std << "; ";
  }
  if (accel_std > config_.max_accel_std) {
    out << "accelerometer std " << accel_std << " m/s^2 exceeds " << config_.max_accel_std << "; ";
  }
  const double gravity = (accel_sum_ / count_).norm();
  if (std::abs(gravity - 9.80665) > 1.0) {
    out << "mean specific force " << gravity << " m/s^2 is far from gravity; ";
  }
  const std::string text = out.str();
  return text.empty() ? "" : "the rig was not still during calibration: " + text;
}

void StillPhaseCalibrator::reset() { *this = StillPhaseCalibrator(config_); }

}  // namespace vicc_tracking
