#pragma once
// dynamic_reconfigure of the tracker's tuning while it runs: the ICP thresholds on ~icp
// (cfg/IcpTuning.cfg) and the EKF noise on ~ekf (cfg/EkfTuning.cfg), under the keys of the
// parameter tables. Frames, topics and the pyramid layout stay start-up parameters.

#include "vicc_tracking/EkfTuningConfig.h"
#include "vicc_tracking/IcpTuningConfig.h"
#include "vicc_tracking/ros/reconfigurable_section.hpp"
#include "vicc_tracking/tracker.hpp"

namespace vicc_tracking {

/// The .cfg's fields from the config structs and back; fields the .cfg does not cover
/// (iterations_per_level, imu_noise_file) keep the values of `base`.
IcpTuningConfig toTuning(const IcpConfig& icp);
IcpConfig fromTuning(const IcpTuningConfig& tuning, IcpConfig base);
EkfTuningConfig toTuning(const EkfConfig& ekf);
EkfConfig fromTuning(const EkfTuningConfig& tuning, EkfConfig base);

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
