#pragma once
// The fusion node's private namespace as YAML without ROS: the tracker's keys
// (vicc_tracking/config/tracker.yaml) and the fusion's (config/fusion.yaml) share it, so a
// file in either layout, or both merged, is read through all four tables.

#include <string>

#include "vicc_fusion/fusion_parameters.hpp"
#include "vicc_tracking/tracker_config_yaml.hpp"

namespace vicc_fusion {

struct FusionParameterSet {
  vicc_tracking::TrackerParameterSet tracker;
  FusionRosSettings node;  ///< accepted so the node's file loads; offline tools ignore it
  FrameToModelConfig model;
};

/// Reads YAML text over `parameters`: keys in the text override, keys left out keep what
/// `parameters` holds, so several files apply in order. Throws std::invalid_argument
/// "<source>: <key path>: <problem>" for invalid YAML, an unknown key, a wrong type or a value
/// a validate() rejects. ekf/imu_noise_file is read, not applied (applyImuNoiseFile).
void readFusionParameters(const std::string& yaml_text, const std::string& source,
                          FusionParameterSet& parameters);

/// readFusionParameters() of a file; the messages name the file.
void loadFusionParameters(const std::string& path, FusionParameterSet& parameters);

}  // namespace vicc_fusion
