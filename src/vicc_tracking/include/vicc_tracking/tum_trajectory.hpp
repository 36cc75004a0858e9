#pragma once
// TUM RGB-D trajectory format: one "t tx ty tz qx qy qz qw" line per pose.

#include <string>
#include <vector>

#include <Eigen/Geometry>

namespace vicc_tracking {

struct TimedPose {
  double stamp = 0.0;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
};

std::string formatTumLine(const TimedPose& pose);
/// Throws std::runtime_error naming the file and line on a malformed line; '#' comments
/// and blank lines are skipped.
std::vector<TimedPose> readTumTrajectory(const std::string& path);
void writeTumTrajectory(const std::string& path, const std::vector<TimedPose>& poses);

}  // namespace vicc_tracking
