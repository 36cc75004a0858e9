#include "vicc_tracking/sim/extrapolation_error.hpp"

#include <cmath>
#include <stdexcept>

#include "vicc_tracking/virtual_measurement.hpp"

namespace vicc_tracking::sim {
namespace {

/// Central difference of the true IMU position: the velocity the IMU-aided virtual velocity
/// (velocityAtIntervalEnd) approximates.
Eigen::Vector3d trueVelocity(const RigSimulator& rig, double t) {
  const double h = 1e-4;
  return (rig.imuPose(t + h).translation() - rig.imuPose(t - h).translation()) / (2.0 * h);
}

double slope(const std::vector<double>& x, const std::vector<double>& y) {
  double mean_x = 0.0, mean_y = 0.0;
  for (size_t i = 0; i < x.size(); ++i) mean_x += x[i] / x.size(), mean_y += y[i] / y.size();
  double covariance = 0.0, variance = 0.0;
  for (size_t i = 0; i < x.size(); ++i) {
    covariance += (x[i] - mean_x) * (y[i] - mean_y);
    variance += (x[i] - mean_x) * (x[i] - mean_x);
  }
  return covariance / variance;
}

}  // namespace

ExtrapolationError measureExtrapolationError(const RigSimulator& rig, int frame_step) {
  if (frame_step < 1) throw std::invalid_argument("frame_step must be >= 1");
  std::vector<double> times;
  const std::vector<double>& all = rig.depthTimes();
  for (size_t i = 0; i < all.size(); i += frame_step) times.push_back(all[i]);
  if (times.size() < 4) throw std::invalid_argument("too few depth frames for the frame step");

  ExtrapolationError error;
  error.frame_step = frame_step;
  error.interval = times[1] - times[0];
  for (size_t i = 2; i + 1 < times.size(); ++i) {
    PoseHistory history;
    for (size_t k = i - 2; k <= i; ++k) {
      history.push(StampedPose::fromIsometry(times[k], rig.imuPose(times[k])));
    }
    const std::vector<Eigen::Vector3d> velocities = {trueVelocity(rig, times[i]),
                                                     trueVelocity(rig, times[i - 1])};
    const double interval = times[i + 1] - times[i];
    const Vector14d z = virtualMeasurement(history, interval, velocities);

    const StampedPose now = StampedPose::fromIsometry(times[i], rig.imuPose(times[i]));
    const StampedPose next = StampedPose::fromIsometry(times[i + 1], rig.imuPose(times[i + 1]));
    const Quat4 true_rotation = multiply(conjugate(now.orientation), next.orientation);
    const Quat4 rotation_error = z.segment<4>(0) - alignedTo(true_rotation, z.segment<4>(0));
    error.rotation += rotation_error.squaredNorm() / 4.0;
    error.velocity += (z.segment<3>(4) - trueVelocity(rig, times[i + 1])).squaredNorm() / 3.0;
    error.position += (z.segment<3>(7) - (next.position - now.position)).squaredNorm() / 3.0;
    ++error.samples;
  }
  error.rotation /= error.samples;
  error.velocity /= error.samples;
  error.position /= error.samples;
  return error;
}

IntervalExponents fitIntervalExponents(const std::vector<ExtrapolationError>& errors) {
  if (errors.size() < 2) throw std::invalid_argument("need errors at two intervals at least");
  std::vector<double> log_interval, log_rotation, log_velocity, log_position;
  for (const ExtrapolationError& error : errors) {
    log_interval.push_back(std::log(error.interval));
    log_rotation.push_back(std::log(error.rotation));
    log_velocity.push_back(std::log(error.velocity));
    log_position.push_back(std::log(error.position));
  }
  return {slope(log_interval, log_rotation), slope(log_interval, log_velocity),
          slope(log_interval, log_position)};
}

}  // namespace vicc_tracking::sim
