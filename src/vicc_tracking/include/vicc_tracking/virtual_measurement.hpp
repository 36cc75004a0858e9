#pragma once
// Virtual measurements of thesis 5.4.2: motion extrapolated from the last ICP poses.

#include <deque>
#include <vector>

#include <Eigen/Geometry>

#include "vicc_tracking/ekf.hpp"

namespace vicc_tracking {

/// A tracked pose (of the IMU body in the map frame) at a depth frame.
struct StampedPose {
  double stamp = 0.0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Quat4 orientation = identityQuat();

  static StampedPose fromIsometry(double stamp, const Eigen::Isometry3d& pose);
  Eigen::Isometry3d toIsometry() const;
};

/// The last three tracked poses, newest at the back.
class PoseHistory {
 public:
  void push(const StampedPose& pose);
  void clear() { poses_.clear(); }
  size_t size() const { return poses_.size(); }
  bool empty() const { return poses_.empty(); }
  /// back(0) is the newest pose, back(1) the one before, ...
  const StampedPose& back(size_t age = 0) const { return poses_[poses_.size() - 1 - age]; }

 private:
  std::deque<StampedPose> poses_;
};

/// z_{i+1} = [q^e v^e p^e q_b^ICP] (Eq. 5.9) from Eq. 5.10-5.15, for the interval of length
/// interval_dt that starts at the newest pose in history.
/// velocities: the velocity at the newest and at the one-older pose (newest first), when
/// known better than by the backward differences of Eq. 5.10 (see velocityAtIntervalEnd).
Vector14d virtualMeasurement(const PoseHistory& history, double interval_dt,
                             const std::vector<Eigen::Vector3d>& velocities = {});

}  // namespace vicc_tracking
