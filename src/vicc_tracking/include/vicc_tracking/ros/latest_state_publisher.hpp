#pragma once
// A latched topic whose message is built from state that changes with every frame (the tracked
// path, the fused model). Building and sending it is paid only while someone subscribes, and
// the fused model is throttled; on their own, both would leave a subscriber that connects after
// the last frame (rviz opened after a replay, or slow to start) with nothing or with a state
// that misses the last frames. This publishes the latest state when it changed since the last
// publication and either
// - a frame reports the change and at least `min_period` (stamp time) has passed since the last
//   publication (the throttle, in the recording's time like the frames), or
// - no frame has reported anything for kQuietSeconds (wall clock: after a replay /clock
//   stands still, so stamp time would never catch up); this also serves a subscriber that
//   connects after the last frame.
// Its callbacks run on the node handle's callback queue, like the frames that change the state.

#include <functional>

#include <ros/ros.h>

namespace vicc_tracking {

class LatestStatePublisher {
 public:
  /// `publish` builds the message from the current state and publishes it on `publisher`
  /// (latched). `min_period` <= 0: every change is published at once (with subscribers).
  LatestStatePublisher(ros::NodeHandle& nh, const ros::Publisher& publisher, double min_period_s,
                       std::function<void(const ros::Time&)> publish);

  /// The state changed with the frame stamped `stamp`: publishes now if the throttle allows.
  void changed(const ros::Time& stamp);
  /// Wall-clock seconds without a frame after which the latest state is published anyway:
  /// long against a live stream's frame interval, short for someone waiting for the result.
  static constexpr double kQuietSeconds = 1.0;

 private:
  void publishNow();
  void onFlushTimer(const ros::WallTimerEvent&);

  ros::Publisher publisher_;
  double min_period_s_;
  std::function<void(const ros::Time&)> publish_;
  ros::WallTimer flush_timer_;
  bool unpublished_change_ = false;
  ros::Time last_change_stamp_;
  ros::Time last_publication_stamp_;
  ros::WallTime last_change_wall_;
};

}  // namespace vicc_tracking
