#pragma once
// The simulator's publishers run as separate processes (like the real drivers) but must
// share one time base: both read the start time from a parameter on the master.

#include <string>

#include <ros/node_handle.h>
#include <ros/time.h>

#include "vicc_tracking/sim/rig_simulator.hpp"

namespace vicc_tracking {

/// The start time of the simulated recording: /vicc_rig/t0 if it is set and recent,
/// otherwise a new one (next full second + 1 s) that the other publisher then reads.
ros::Time negotiateRigStartTime(ros::NodeHandle& nh);

/// Period of a looped run: the trajectory closes its loop and is still at both ends, so
/// repeating it is continuous.
double loopPeriod(const sim::RigSimulator& rig);

}  // namespace vicc_tracking
