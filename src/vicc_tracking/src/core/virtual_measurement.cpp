#include "vicc_tracking/virtual_measurement.hpp"

#include <stdexcept>

namespace vicc_tracking {

StampedPose StampedPose::fromIsometry(double stamp, const Eigen::Isometry3d& pose) {
  StampedPose result;
  result.stamp = stamp;
  result.position = pose.translation();
  result.orientation = toQuat4(Eigen::Quaterniond(pose.rotation()));
  return result;
}

Eigen::Isometry3d StampedPose::toIsometry() const {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = toEigen(orientation).toRotationMatrix();
  pose.translation() = position;
  return pose;
}

void PoseHistory::push(const StampedPose& pose) {
  StampedPose aligned = pose;
  // Keep consecutive quaternions in one hemisphere so their differences (Eq. 5.12) make sense.
  if (!poses_.empty()) aligned.orientation = alignedTo(pose.orientation, poses_.back().orientation);
  poses_.push_back(aligned);
  if (poses_.size() > 3) poses_.pop_front();
}

namespace {

/// Eq. 5.10: backward-Euler velocity at history entry `age`.
Eigen::Vector3d velocityAt(const PoseHistory& history, size_t age) {
  if (history.size() < age + 2) return Eigen::Vector3d::Zero();
  const StampedPose& newer = history.back(age);
  const StampedPose& older = history.back(age + 1);
  const double dt = newer.stamp - older.stamp;
  if (dt <= 0.0) return Eigen::Vector3d::Zero();
  return (newer.position - older.position) / dt;
}

}  // namespace

Vector14d virtualMeasurement(const PoseHistory& history, double interval_dt,
                             const std::vector<Eigen::Vector3d>& velocities) {
  if (history.empty()) throw std::logic_error("virtualMeasurement needs at least one pose");
  const StampedPose& current = history.back();
  const Eigen::Vector3d velocity =
      velocities.size() >= 1 ? velocities[0] : velocityAt(history, 0);  // Eq. 5.10
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();   // Eq. 5.11
  Quat4 angular_velocity_quat = identityQuat();             // Eq. 5.12, i = 0
  if (history.size() >= 2) {
    const StampedPose& previous = history.back(1);
    const double dt_previous = current.stamp - previous.stamp;
    if (dt_previous > 0.0) {
      if (velocities.size() >= 2) {
        acceleration = (velocity - velocities[1]) / dt_previous;
      } else if (history.size() >= 3) {
        acceleration = (velocity - velocityAt(history, 1)) / dt_previous;
      }
      angular_velocity_quat = multiply(
          (2.0 / dt_previous) * (current.orientation - previous.orientation),
          conjugate(previous.orientation));
    }
  }

  // Eq. 5.13 with the thesis's footnote 2: the predicted frame-to-frame rotation.
  const Quat4 extrapolated =
      current.orientation + 0.5 * interval_dt * multiply(angular_velocity_quat, current.orientation);
  const Quat4 rotation = multiply(conjugate(current.orientation), extrapolated).normalized();

  Vector14d z;
  z << rotation,                                 // q^e
      velocity + interval_dt * acceleration,     // v^e, Eq. 5.14
      interval_dt * velocity,                    // p^e, Eq. 5.15
      current.orientation;                       // q_b^ICP
  return z;
}

}  // namespace vicc_tracking
