#include "vicc_tracking/ros/tracker_reconfigure.hpp"

namespace vicc_tracking {

TrackerReconfigure::TrackerReconfigure(const ros::NodeHandle& private_nh,
                                       const TrackerConfig& initial)
    : icp_(ros::NodeHandle(private_nh, "icp"), "tracker: icp", initial.icp),
      ekf_(ros::NodeHandle(private_nh, "ekf"), "tracker: ekf", initial.ekf) {}

void TrackerReconfigure::applyPending(TrackerConfig& config, Tracker* tracker) {
  if (const std::optional<IcpConfig> icp = icp_.takeChange()) {
    if (tracker) tracker->setIcpConfig(*icp);
    config.icp = *icp;
  }
  if (const std::optional<EkfConfig> ekf = ekf_.takeChange()) {
    if (tracker) tracker->setEkfConfig(*ekf);
    config.ekf = *ekf;
  }
}

}  // namespace vicc_tracking
