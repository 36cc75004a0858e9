#include "vicc_tracking/ros/rig_clock.hpp"

#include <cmath>

#include <ros/console.h>

namespace vicc_tracking {
namespace {
const char* kStartParam = "/vicc_rig/t0";
constexpr double kMaxStartAge = 3.0;  // s; an older t0 is left over from a previous run
}  // namespace

ros::Time negotiateRigStartTime(ros::NodeHandle& nh) {
  double t0 = 0.0;
  const double now = ros::Time::now().toSec();
  if (!nh.getParam(kStartParam, t0) || t0 < now - kMaxStartAge) {
    nh.setParam(kStartParam, std::ceil(now) + 1.0);
    // Another publisher may have written at the same moment; the last write wins for both.
    ros::WallDuration(0.2).sleep();
    nh.getParam(kStartParam, t0);
  }
  return ros::Time(t0);
}

double loopPeriod(const sim::RigSimulator& rig) {
  return rig.duration() + 1.0 / rig.scenario().imu.rate_hz;
}

}  // namespace vicc_tracking
