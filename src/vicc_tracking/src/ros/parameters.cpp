#include "vicc_tracking/ros/parameters.hpp"

#include <stdexcept>

namespace vicc_tracking {
namespace {

void readPreprocessing(const ros::NodeHandle& nh, PreprocessingConfig& config) {
  readOptionalParam(nh, "pyramid_levels", config.pyramid_levels);
  readOptionalParam(nh, "min_depth", config.min_depth);
  readOptionalParam(nh, "max_depth", config.max_depth);
  readOptionalParam(nh, "bilateral_filter", config.bilateral_filter);
  readOptionalParam(nh, "bilateral_diameter", config.bilateral_diameter);
  readOptionalParam(nh, "bilateral_sigma_depth", config.bilateral_sigma_depth);
  readOptionalParam(nh, "bilateral_sigma_space", config.bilateral_sigma_space);
  readOptionalParam(nh, "pyramid_depth_threshold", config.pyramid_depth_threshold);
  readOptionalParam(nh, "normal_depth_jump", config.normal_depth_jump);
}

void readIcp(const ros::NodeHandle& nh, IcpConfig& config) {
  readOptionalParam(nh, "iterations_per_level", config.iterations_per_level);
  readOptionalParam(nh, "max_correspondence_distance", config.max_correspondence_distance);
  readOptionalParam(nh, "max_normal_angle_deg", config.max_normal_angle_deg);
  readOptionalParam(nh, "convergence_translation", config.convergence_translation);
  readOptionalParam(nh, "convergence_rotation_deg", config.convergence_rotation_deg);
  readOptionalParam(nh, "min_inliers", config.min_inliers);
  readOptionalParam(nh, "min_inlier_ratio", config.min_inlier_ratio);
  readOptionalParam(nh, "max_condition_number", config.max_condition_number);
  readOptionalParam(nh, "max_jump_translation", config.max_jump_translation);
  readOptionalParam(nh, "max_jump_rotation_deg", config.max_jump_rotation_deg);
}

void readEkf(const ros::NodeHandle& nh, EkfConfig& config) {
  readOptionalParam(nh, "process_noise_rotation", config.process_noise_rotation);
  readOptionalParam(nh, "process_noise_velocity", config.process_noise_velocity);
  readOptionalParam(nh, "process_noise_position", config.process_noise_position);
  readOptionalParam(nh, "process_noise_base", config.process_noise_base);
  readOptionalParam(nh, "measurement_noise_rotation", config.measurement_noise_rotation);
  readOptionalParam(nh, "measurement_noise_velocity", config.measurement_noise_velocity);
  readOptionalParam(nh, "measurement_noise_position", config.measurement_noise_position);
  readOptionalParam(nh, "measurement_noise_base", config.measurement_noise_base);
  readOptionalParam(nh, "initial_covariance", config.initial_covariance);
  readOptionalParam(nh, "imu_aided_virtual_velocity", config.imu_aided_virtual_velocity);
}

template <typename Config>
void validateSection(const ros::NodeHandle& nh, const Config& config) {
  try {
    config.validate();
  } catch (const std::exception& error) {
    throw std::invalid_argument("parameters under " + nh.getNamespace() + ": " + error.what());
  }
}

}  // namespace

TrackerConfig readTrackerConfig(const ros::NodeHandle& private_nh) {
  TrackerConfig config;
  std::string strategy = toString(config.init_strategy);
  readOptionalParam(private_nh, "init_strategy", strategy);
  try {
    config.init_strategy = initStrategyFromString(strategy);
  } catch (const std::exception& error) {
    throw std::invalid_argument("parameter " + private_nh.resolveName("init_strategy") + ": " +
                                error.what());
  }
  readOptionalParam(private_nh, "wait_for_imu", config.wait_for_imu);

  const ros::NodeHandle preprocessing_nh(private_nh, "preprocessing");
  const ros::NodeHandle icp_nh(private_nh, "icp");
  const ros::NodeHandle ekf_nh(private_nh, "ekf");
  const ros::NodeHandle still_nh(private_nh, "still_phase");
  const ros::NodeHandle sync_nh(private_nh, "imu_sync");
  readPreprocessing(preprocessing_nh, config.preprocessing);
  readIcp(icp_nh, config.icp);
  readEkf(ekf_nh, config.ekf);
  readOptionalParam(still_nh, "duration", config.still_phase.duration);
  readOptionalParam(still_nh, "max_gyro_std", config.still_phase.max_gyro_std);
  readOptionalParam(still_nh, "max_accel_std", config.still_phase.max_accel_std);
  readOptionalParam(sync_nh, "max_gap", config.synchronizer.max_gap);
  readOptionalParam(sync_nh, "clock_jump", config.synchronizer.clock_jump);
  readOptionalParam(sync_nh, "max_buffered", config.synchronizer.max_buffered);

  validateSection(preprocessing_nh, config.preprocessing);
  validateSection(icp_nh, config.icp);
  validateSection(ekf_nh, config.ekf);
  validateSection(still_nh, config.still_phase);
  validateSection(sync_nh, config.synchronizer);
  validateSection(private_nh, config);
  return config;
}

}  // namespace vicc_tracking
