#pragma once
// The tracker's parameter tables, ROS-free: one table of (key, field) per config struct.
// Every reader and writer of the parameters walks these tables, so a key is named in one
// place only: the ROS parameter reader (ros/parameters.hpp), the YAML file reader
// (tracker_config_yaml.hpp, used by the offline tools) and the YAML/JSON writers.
//
// The readers and writers are vicc_common's (parameter_types.hpp describes the visitor):
//   visitor(key, field)               for a value: int, double, bool, std::string,
//                                     std::vector<int> or InitStrategyType (stored as text)
//   visitor.section(key, sub_config)  for a nested section; the visitor goes on with
//                                     visitParameters(sub_config, ...)
// Config may be const (writers) or not (readers). Keys follow config/tracker.yaml.

#include <string>
#include <type_traits>

#include "vicc_tracking/imu_noise.hpp"
#include "vicc_tracking/tracker.hpp"

namespace vicc_tracking {

/// Settings only the tracker node uses (frames, tf, path, queueing). Plain data, kept in the
/// core so that offline tools accept the node's parameter file as it is.
struct TrackerNodeSettings {
  std::string map_frame = "map";
  /// Frame whose pose in map is published on tf. Empty: the IMU frame (the root of the rig's
  /// static tree in the usual setup), so map -> imu -> camera stays a tree.
  std::string tf_child_frame;
  bool publish_tf = true;
  int max_path_length = 5000;
  /// Depth frames held back waiting for IMU data up to their stamp; beyond this the oldest
  /// is processed with the IMU data that is there.
  int max_pending_frames = 3;
  /// If set, the map is aligned so that the first tracked pose equals this frame's pose in
  /// map_frame (e.g. the simulator's ground truth), for side-by-side display.
  std::string initial_pose_frame;
  void validate() const;
};

/// InitStrategyType is stored as its name ("ekf", "constant_velocity", ...).
inline std::string toParameterText(InitStrategyType type) { return toString(type); }
inline void fromParameterText(const std::string& text, InitStrategyType& type) {
  type = initStrategyFromString(text);
}

template <typename Config, typename Type>
using EnableForConfig = std::enable_if_t<std::is_same_v<std::remove_const_t<Config>, Type>>;

template <typename Config, typename Visitor>
EnableForConfig<Config, PreprocessingConfig> visitParameters(Config& config, Visitor& visit) {
  visit("pyramid_levels", config.pyramid_levels);
  visit("min_depth", config.min_depth);
  visit("max_depth", config.max_depth);
  visit("bilateral_filter", config.bilateral_filter);
  visit("bilateral_diameter", config.bilateral_diameter);
  visit("bilateral_sigma_depth", config.bilateral_sigma_depth);
  visit("bilateral_sigma_space", config.bilateral_sigma_space);
  visit("pyramid_depth_threshold", config.pyramid_depth_threshold);
  visit("normal_depth_jump", config.normal_depth_jump);
}

template <typename Config, typename Visitor>
EnableForConfig<Config, IcpConfig> visitParameters(Config& config, Visitor& visit) {
  visit("iterations_per_level", config.iterations_per_level);
  visit("max_correspondence_distance", config.max_correspondence_distance);
  visit("max_normal_angle_deg", config.max_normal_angle_deg);
  visit("convergence_translation", config.convergence_translation);
  visit("convergence_rotation_deg", config.convergence_rotation_deg);
  visit("min_inliers", config.min_inliers);
  visit("min_inlier_ratio", config.min_inlier_ratio);
  visit("max_condition_number", config.max_condition_number);
  visit("max_jump_translation", config.max_jump_translation);
  visit("max_jump_rotation_deg", config.max_jump_rotation_deg);
}

template <typename Config, typename Visitor>
EnableForConfig<Config, EkfConfig> visitParameters(Config& config, Visitor& visit) {
  visit("process_noise_rotation", config.process_noise_rotation);
  visit("process_noise_velocity", config.process_noise_velocity);
  visit("process_noise_position", config.process_noise_position);
  visit("process_noise_base", config.process_noise_base);
  visit("measurement_noise_rotation", config.measurement_noise_rotation);
  visit("measurement_noise_velocity", config.measurement_noise_velocity);
  visit("measurement_noise_position", config.measurement_noise_position);
  visit("measurement_noise_base", config.measurement_noise_base);
  visit("initial_covariance", config.initial_covariance);
  visit("measurement_noise_reference_interval", config.measurement_noise_reference_interval);
  visit("measurement_noise_interval_exponent", config.measurement_noise_interval_exponent);
  visit("imu_aided_virtual_velocity", config.imu_aided_virtual_velocity);
  visit("imu_noise_file", config.imu_noise_file);
}

/// The keys of Kalibr's imu.yaml (and of the VIO tools that read it), plus one extension.
template <typename Config, typename Visitor>
EnableForConfig<Config, ImuNoise> visitParameters(Config& config, Visitor& visit) {
  visit("accelerometer_noise_density", config.accelerometer_noise_density);
  visit("accelerometer_random_walk", config.accelerometer_random_walk);
  visit("gyroscope_noise_density", config.gyroscope_noise_density);
  visit("gyroscope_random_walk", config.gyroscope_random_walk);
  visit("update_rate", config.update_rate);
  visit("rostopic", config.rostopic);
  visit("accelerometer_turn_on_bias", config.accelerometer_turn_on_bias);
}

template <typename Config, typename Visitor>
EnableForConfig<Config, StillPhaseConfig> visitParameters(Config& config, Visitor& visit) {
  visit("duration", config.duration);
  visit("max_gyro_std", config.max_gyro_std);
  visit("max_accel_std", config.max_accel_std);
}

template <typename Config, typename Visitor>
EnableForConfig<Config, SynchronizerConfig> visitParameters(Config& config, Visitor& visit) {
  visit("max_gap", config.max_gap);
  visit("clock_jump", config.clock_jump);
  visit("max_buffered", config.max_buffered);
}

/// The tracker's own keys at the top level, then its sections.
template <typename Config, typename Visitor>
EnableForConfig<Config, TrackerConfig> visitParameters(Config& config, Visitor& visit) {
  visit("init_strategy", config.init_strategy);
  visit("wait_for_imu", config.wait_for_imu);
  visit.section("preprocessing", config.preprocessing);
  visit.section("icp", config.icp);
  visit.section("ekf", config.ekf);
  visit.section("still_phase", config.still_phase);
  visit.section("imu_sync", config.synchronizer);
}

/// Top-level keys next to the tracker's in the node's namespace.
template <typename Config, typename Visitor>
EnableForConfig<Config, TrackerNodeSettings> visitParameters(Config& config, Visitor& visit) {
  visit("map_frame", config.map_frame);
  visit("tf_child_frame", config.tf_child_frame);
  visit("publish_tf", config.publish_tf);
  visit("max_path_length", config.max_path_length);
  visit("max_pending_frames", config.max_pending_frames);
  visit("initial_pose_frame", config.initial_pose_frame);
}

}  // namespace vicc_tracking
