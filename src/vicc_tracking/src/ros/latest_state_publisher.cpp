#include "vicc_tracking/ros/latest_state_publisher.hpp"

#include <utility>

namespace vicc_tracking {

LatestStatePublisher::LatestStatePublisher(ros::NodeHandle& nh, const ros::Publisher& publisher,
                                           double min_period_s,
                                           std::function<void(const ros::Time&)> publish)
    : publisher_(publisher), min_period_s_(min_period_s), publish_(std::move(publish)) {
  // Checks four times per quiet period, so the final state follows the last frame within
  // 1.25 quiet periods.
  flush_timer_ = nh.createWallTimer(ros::WallDuration(kQuietSeconds / 4),
                                    &LatestStatePublisher::onFlushTimer, this);
}

void LatestStatePublisher::changed(const ros::Time& stamp) {
  unpublished_change_ = true;
  last_change_stamp_ = stamp;
  last_change_wall_ = ros::WallTime::now();
  if (publisher_.getNumSubscribers() == 0) return;  // the flush timer serves a late subscriber
  const bool throttled = min_period_s_ > 0.0 && !last_publication_stamp_.isZero() &&
                         stamp >= last_publication_stamp_ &&
                         (stamp - last_publication_stamp_).toSec() < min_period_s_;
  if (!throttled) publishNow();
}

void LatestStatePublisher::publishNow() {
  publish_(last_change_stamp_);
  last_publication_stamp_ = last_change_stamp_;
  unpublished_change_ = false;
}

void LatestStatePublisher::onFlushTimer(const ros::WallTimerEvent&) {
  if (!unpublished_change_ || publisher_.getNumSubscribers() == 0) return;
  const double quiet_s = (ros::WallTime::now() - last_change_wall_).toSec();
  if (quiet_s >= kQuietSeconds) publishNow();
}

}  // namespace vicc_tracking
