#pragma once
// The tracker node's parameter file (config/tracker.yaml layout) read and written without
// ROS, through the tables of tracker_parameters.hpp: offline tools run with any parameter set
// the node can.

#include <string>

#include "vicc_tracking/tracker_parameters.hpp"

namespace vicc_tracking {

struct TrackerParameterSet {
  TrackerConfig tracker;
  TrackerNodeSettings node;  ///< accepted so the node's file loads; offline tools ignore it
};

/// Parses YAML text in the layout of config/tracker.yaml. Keys left out keep their defaults.
/// Throws std::invalid_argument "<source>: <key path>: <problem>" for invalid YAML, an unknown
/// key, a value of the wrong type or a value the config's validate() rejects.
TrackerParameterSet parseTrackerParameters(const std::string& yaml_text,
                                           const std::string& source = "tracker parameters");

/// Reads a file with parseTrackerParameters(); the messages name the file.
TrackerParameterSet loadTrackerParameters(const std::string& path);

/// Kalibr's imu.yaml layout (top-level keys of the ImuNoise table in tracker_parameters.hpp).
/// Throws std::invalid_argument "<source>: <key>: <problem>" for invalid YAML, an unknown key,
/// a wrong type or a missing/invalid figure.
ImuNoise parseImuNoise(const std::string& yaml_text, const std::string& source = "IMU noise");
ImuNoise loadImuNoise(const std::string& path);

/// If config.ekf.imu_noise_file is set: Q derived from that file (ekfNoiseFromImu). Both the
/// YAML and the ROS parameter readers call it; errors name the file.
void applyImuNoiseFile(TrackerConfig& config);

/// YAML in the same layout with every parameter; parseTrackerParameters() reads it back.
std::string toYaml(const TrackerParameterSet& parameters);

}  // namespace vicc_tracking
