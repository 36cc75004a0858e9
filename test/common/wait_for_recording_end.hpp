#pragma once
// Shared by the rostests that play a recording into a node: spin until the node has gone
// quiet (no new message for `quiet` after at least `min_messages`), or the overall limit.

#include <cstddef>
#include <functional>

#include <ros/ros.h>

namespace vicc_test {

/// `count` returns how many messages the test has received so far.
inline void waitForRecordingEnd(const std::function<std::size_t()>& count,
                                std::size_t min_messages = 20,
                                ros::WallDuration quiet = ros::WallDuration(3.0),
                                ros::WallDuration limit = ros::WallDuration(150.0)) {
  const ros::WallTime deadline = ros::WallTime::now() + limit;
  ros::WallTime last_change = ros::WallTime::now();
  std::size_t last_count = 0;
  while (ros::ok() && ros::WallTime::now() < deadline) {
    ros::spinOnce();
    ros::WallDuration(0.02).sleep();
    if (count() != last_count) {
      last_count = count();
      last_change = ros::WallTime::now();
    }
    if (last_count > min_messages && ros::WallTime::now() - last_change > quiet) break;
  }
}

}  // namespace vicc_test
