#pragma once
// Fills the core configuration structs from ROS parameters (voxblox style: free functions,
// the core stays ROS-free). Unknown types or invalid values throw std::invalid_argument
// naming the parameter, so a node fails loudly at start instead of running misconfigured.

#include <string>
#include <vector>

#include <ros/node_handle.h>

#include "vicc_tracking/tracker_parameters.hpp"

namespace vicc_tracking {

/// Reads `name` into `value` if it is set; leaves the default otherwise. Throws if the
/// parameter exists with an incompatible type.
template <typename T>
void readOptionalParam(const ros::NodeHandle& nh, const std::string& name, T& value) {
  if (!nh.hasParam(name)) return;
  T read_value{};
  if (!nh.getParam(name, read_value)) {
    throw std::invalid_argument("parameter " + nh.resolveName(name) + " has the wrong type");
  }
  value = read_value;
}

/// Parameters in the node's private namespace: init_strategy, wait_for_imu, preprocessing/*,
/// icp/*, ekf/*, still_phase/*, imu_sync/* (the keys are the tables of tracker_parameters.hpp;
/// config/tracker.yaml lists them with their defaults). Each section is validated.
TrackerConfig readTrackerConfig(const ros::NodeHandle& private_nh);

/// The node-only settings (map_frame, tf_child_frame, publish_tf, ...) in the same namespace.
TrackerNodeSettings readTrackerNodeSettings(const ros::NodeHandle& private_nh);

}  // namespace vicc_tracking
