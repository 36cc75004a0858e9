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

}  // namespace vicc_tracking
