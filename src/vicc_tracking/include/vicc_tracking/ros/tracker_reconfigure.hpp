#pragma once
// dynamic_reconfigure of the tracker's tuning while it runs: the ICP thresholds on ~icp
// (cfg/IcpTuning.cfg) and the EKF noise on ~ekf (cfg/EkfTuning.cfg), under the keys of the
// parameter tables, which convert between the .cfg and the config structs (toTuning and
// fromTuning of reconfigure_table.hpp); the fields the .cfg leaves out (iterations_per_level,
// imu_noise_file) stay start-up parameters, as do frames, topics and the pyramid layout.

#include "vicc_tracking/EkfTuningConfig.h"
#include "vicc_tracking/IcpTuningConfig.h"
#include "vicc_tracking/ros/reconfigurable_section.hpp"
#include "vicc_tracking/tracker.hpp"
#include "vicc_tracking/tracker_parameters.hpp"

namespace vicc_tracking {

class TrackerReconfigure {
 public:
  /// Serves `initial`'s ICP and EKF sections under private_nh/icp and private_nh/ekf.
  TrackerReconfigure(const ros::NodeHandle& private_nh, const TrackerConfig& initial);

  /// Moves the changes accepted since the last call into `config` and, once tracking runs,
  /// into `tracker` (null before). Call from the frame callback, between two frames.
  void applyPending(TrackerConfig& config, Tracker* tracker);

 private:
  ReconfigurableSection<IcpConfig, IcpTuningConfig> icp_;
  ReconfigurableSection<EkfConfig, EkfTuningConfig> ekf_;
};

}  // namespace vicc_tracking
