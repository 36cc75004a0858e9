#include "vicc_tracking/tum_trajectory.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace vicc_tracking {

std::string formatTumLine(const TimedPose& pose) {
  const Eigen::Quaterniond q(pose.pose.linear());
  const Eigen::Vector3d& t = pose.pose.translation();
  char line[256];
  std::snprintf(line, sizeof(line), "%.9f %.6f %.6f %.6f %.9f %.9f %.9f %.9f", pose.stamp, t.x(),
                t.y(), t.z(), q.x(), q.y(), q.z(), q.w());
  return line;
}

std::vector<TimedPose> readTumTrajectory(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read trajectory " + path);
  std::vector<TimedPose> poses;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    double v[8];
    for (double& value : v) fields >> value;
    const Eigen::Quaterniond q(v[7], v[4], v[5], v[6]);
    bool finite = true;
    for (const double value : v) finite = finite && std::isfinite(value);
    if (!fields || !finite || std::abs(q.norm() - 1.0) > 1e-3) {
      throw std::runtime_error(path + ":" + std::to_string(number) +
                               ": expected 't tx ty tz qx qy qz qw' with a unit quaternion");
    }
    TimedPose pose;
    pose.stamp = v[0];
    pose.pose.linear() = q.normalized().toRotationMatrix();
    pose.pose.translation() = Eigen::Vector3d(v[1], v[2], v[3]);
    poses.push_back(pose);
  }
  return poses;
}

void writeTumTrajectory(const std::string& path, const std::vector<TimedPose>& poses) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write trajectory " + path);
  out << "# timestamp tx ty tz qx qy qz qw (camera optical frame in map)\n";
  for (const TimedPose& pose : poses) out << formatTumLine(pose) << "\n";
  if (!out) throw std::runtime_error("error while writing " + path);
}

}  // namespace vicc_tracking
