#pragma once
// Fills the core configuration structs from ROS parameters (voxblox style: free functions,
// the core stays ROS-free) through vicc_common's reader on the tables of
// tracker_parameters.hpp. Wrong types or invalid values throw std::invalid_argument naming the
// parameter, so a node fails loudly at start instead of running misconfigured.

#include <set>
#include <string>

#include <ros/node_handle.h>

#include "vicc_tracking/tracker_parameters.hpp"

namespace vicc_tracking {

/// Parameters in the node's private namespace: init_strategy, wait_for_imu, preprocessing/*,
/// icp/*, ekf/*, still_phase/*, imu_sync/* (the keys are the tables of tracker_parameters.hpp;
/// config/tracker.yaml lists them with their defaults). Each section is validated; the
/// resolved names of the keys are added to `read_names` (for the unknown-key warning).
TrackerConfig readTrackerConfig(const ros::NodeHandle& private_nh,
                                std::set<std::string>& read_names);

/// The node-only settings (map_frame, tf_child_frame, publish_tf, ...) in the same namespace.
TrackerNodeSettings readTrackerNodeSettings(const ros::NodeHandle& private_nh,
                                            std::set<std::string>& read_names);

}  // namespace vicc_tracking
