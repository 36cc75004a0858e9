#pragma once
// Hand-held camera motion around a look-at target. Keyframes (azimuth, elevation, radius,
// roll) are joined by quintic minimum-jerk segments that start and end at rest: smooth
// (C2, so the IMU sees finite jerk-free readings) yet with abrupt direction changes at
// every keyframe, like the thesis's fast hand-held sequences.

#include <vector>

#include <Eigen/Geometry>

namespace vicc_tracking::sim {

struct Keyframe {
  double time = 0.0;           ///< s after the start still phase
  double azimuth_deg = 0.0;    ///< around the target's z axis
  double elevation_deg = 30.0;
  double radius = 0.6;         ///< m, camera to target
  double roll_deg = 0.0;       ///< about the optical axis
};

struct TrajectoryConfig {
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  double still_start = 2.0;  ///< s at rest before the first keyframe (IMU still phase)
  double still_end = 1.0;
  std::vector<Keyframe> keyframes;  ///< the last must equal the first: a closed loop
  /// Throws std::invalid_argument naming the problem.
  void validate() const;
};

class Trajectory {
 public:
  explicit Trajectory(const TrajectoryConfig& config);
  double duration() const;
  /// T_map_camera, camera = optical frame (x right, y down, z forward); map z up.
  Eigen::Isometry3d cameraPose(double t) const;

 private:
  Keyframe interpolate(double t) const;
  TrajectoryConfig config_;
};

}  // namespace vicc_tracking::sim
