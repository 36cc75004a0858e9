#include "vicc_tracking/sim/trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace vicc_tracking::sim {
namespace {

double degrees(double value) { return value * M_PI / 180.0; }

/// Minimum-jerk blend 10s^3 - 15s^4 + 6s^5: zero velocity and acceleration at both ends.
double minimumJerk(double s) { return s * s * s * (10.0 + s * (-15.0 + 6.0 * s)); }

bool sameView(const Keyframe& a, const Keyframe& b) {
  return std::abs(a.azimuth_deg - b.azimuth_deg) < 1e-9 &&
         std::abs(a.elevation_deg - b.elevation_deg) < 1e-9 &&
         std::abs(a.radius - b.radius) < 1e-12 && std::abs(a.roll_deg - b.roll_deg) < 1e-9;
}

}  // namespace

void TrajectoryConfig::validate() const {
  if (!(still_start >= 0.0) || !(still_end >= 0.0)) {
    throw std::invalid_argument("trajectory: still_start and still_end must be >= 0");
  }
  if (keyframes.size() < 2) throw std::invalid_argument("trajectory: needs at least 2 keyframes");
  if (keyframes.front().time != 0.0) {
    throw std::invalid_argument("trajectory: the first keyframe must be at time 0");
  }
  for (size_t i = 0; i < keyframes.size(); ++i) {
    const Keyframe& k = keyframes[i];
    if (!std::isfinite(k.time) || !std::isfinite(k.azimuth_deg) || !std::isfinite(k.elevation_deg) ||
        !std::isfinite(k.radius) || !std::isfinite(k.roll_deg)) {
      throw std::invalid_argument("trajectory: keyframe " + std::to_string(i) + " is not finite");
    }
    if (!(k.radius > 0.05)) {
      throw std::invalid_argument("trajectory: keyframe " + std::to_string(i) +
                                  " radius must be > 0.05 m");
    }
    if (std::abs(k.elevation_deg) >= 89.0) {
      throw std::invalid_argument("trajectory: keyframe " + std::to_string(i) +
                                  " elevation must be within (-89, 89) degrees");
    }
    if (i > 0 && !(k.time > keyframes[i - 1].time)) {
      throw std::invalid_argument("trajectory: keyframe times must increase (keyframe " +
                                  std::to_string(i) + ")");
    }
  }
  if (!sameView(keyframes.front(), keyframes.back())) {
    throw std::invalid_argument("trajectory: the last keyframe must equal the first (closed loop)");
  }
}

Trajectory::Trajectory(const TrajectoryConfig& config) : config_(config) { config_.validate(); }

double Trajectory::duration() const {
  return config_.still_start + config_.keyframes.back().time + config_.still_end;
}

Keyframe Trajectory::interpolate(double t) const {
  const auto& keys = config_.keyframes;
  const double local = std::clamp(t - config_.still_start, 0.0, keys.back().time);
  const auto next = std::upper_bound(keys.begin(), keys.end(), local,
                                     [](double time, const Keyframe& k) { return time < k.time; });
  if (next == keys.end()) return keys.back();
  const Keyframe& a = *(next - 1);
  const Keyframe& b = *next;
  const double s = minimumJerk((local - a.time) / (b.time - a.time));
  Keyframe result;
  result.time = local;
  result.azimuth_deg = a.azimuth_deg + s * (b.azimuth_deg - a.azimuth_deg);
  result.elevation_deg = a.elevation_deg + s * (b.elevation_deg - a.elevation_deg);
  result.radius = a.radius + s * (b.radius - a.radius);
  result.roll_deg = a.roll_deg + s * (b.roll_deg - a.roll_deg);
  return result;
}

Eigen::Isometry3d Trajectory::cameraPose(double t) const {
  const Keyframe view = interpolate(t);
  const double azimuth = degrees(view.azimuth_deg);
  const double elevation = degrees(view.elevation_deg);
  const Eigen::Vector3d offset(std::cos(elevation) * std::cos(azimuth),
                               std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
  const Eigen::Vector3d position = config_.target + view.radius * offset;
  // Optical axes: z towards the target, x to the right (horizontal), y down.
  const Eigen::Vector3d z_axis = (-offset).normalized();
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d x_axis = z_axis.cross(up).normalized();
  const Eigen::Vector3d y_axis = z_axis.cross(x_axis);
  Eigen::Matrix3d rotation;
  rotation << x_axis, y_axis, z_axis;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = rotation * Eigen::AngleAxisd(degrees(view.roll_deg), Eigen::Vector3d::UnitZ());
  pose.translation() = position;
  return pose;
}

}  // namespace vicc_tracking::sim
