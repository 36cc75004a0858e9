#include "vicc_tracking/ros/parameters.hpp"

#include "vicc_common/ros_parameters.hpp"
#include "vicc_tracking/tracker_config_yaml.hpp"

namespace vicc_tracking {

TrackerConfig readTrackerConfig(const ros::NodeHandle& private_nh,
                                std::set<std::string>& read_names) {
  TrackerConfig config;
  vicc_common::readRosParameters(private_nh, config, read_names);
  applyImuNoiseFile(config);  // ~ekf/imu_noise_file: Q from the IMU's datasheet figures
  return config;
}

TrackerNodeSettings readTrackerNodeSettings(const ros::NodeHandle& private_nh,
                                            std::set<std::string>& read_names) {
  TrackerNodeSettings settings;
  vicc_common::readRosParameters(private_nh, settings, read_names);
  return settings;
}

}  // namespace vicc_tracking
