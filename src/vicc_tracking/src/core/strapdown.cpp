#include "vicc_tracking/strapdown.hpp"

#include <cmath>

namespace vicc_tracking {

Eigen::Quaterniond integrateGyroClosedForm(const Eigen::Quaterniond& q,
                                           const Eigen::Vector3d& angular_velocity, double dt) {
  const double rate = angular_velocity.norm();
  if (rate * dt < 1e-12) return q;
  const double half_angle = 0.5 * rate * dt;
  const Eigen::Vector3d axis = angular_velocity / rate;
  const Eigen::Quaterniond delta(std::cos(half_angle), axis.x() * std::sin(half_angle),
                                 axis.y() * std::sin(half_angle), axis.z() * std::sin(half_angle));
  return (q * delta).normalized();
}

StrapdownState strapdownStep(const StrapdownState& state, const ImuStep& step,
                             const ImuCalibration& calibration,
                             const Eigen::Vector3d& gravity_ref) {
  StrapdownState next;
  const Eigen::Vector3d acceleration = state.orientation * step.linear_acceleration - gravity_ref;
  next.orientation = integrateGyroClosedForm(
      state.orientation, step.angular_velocity - calibration.gyro_bias, step.dt);
  next.velocity = state.velocity + step.dt * acceleration;
  next.position = state.position + step.dt * state.velocity + 0.5 * step.dt * step.dt * acceleration;
  return next;
}

Eigen::Vector3d velocityAtIntervalEnd(const Eigen::Quaterniond& start_orientation,
                                      const Eigen::Vector3d& start_position,
                                      const Eigen::Vector3d& end_position, double interval,
                                      const std::vector<ImuStep>& steps,
                                      const ImuCalibration& calibration,
                                      const Eigen::Vector3d& gravity_ref) {
  if (!(interval > 0.0)) return Eigen::Vector3d::Zero();
  StrapdownState from_rest;
  from_rest.orientation = start_orientation;
  for (const ImuStep& step : steps) {
    from_rest = strapdownStep(from_rest, step, calibration, gravity_ref);
  }
  return (end_position - start_position - from_rest.position) / interval + from_rest.velocity;
}

}  // namespace vicc_tracking
