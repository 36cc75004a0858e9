#include "vicc_tracking/ros/parameters.hpp"

#include "vicc_tracking/tracker_config_yaml.hpp"

#include <stdexcept>

namespace vicc_tracking {
namespace {

template <typename Config>
void validateSection(const ros::NodeHandle& nh, const Config& config) {
  try {
    config.validate();
  } catch (const std::exception& error) {
    throw std::invalid_argument("parameters under " + nh.getNamespace() + ": " + error.what());
  }
}

/// Reads the parameters of one namespace through the tables of tracker_parameters.hpp: each
/// is optional, a wrong type throws naming it, each section is validated after reading.
class RosParameterReader {
 public:
  explicit RosParameterReader(const ros::NodeHandle& nh) : nh_(nh) {}

  template <typename T>
  void operator()(const char* key, T& field) {
    readOptionalParam(nh_, key, field);
  }

  void operator()(const char* key, InitStrategyType& field) {
    std::string name = toString(field);
    readOptionalParam(nh_, key, name);
    try {
      field = initStrategyFromString(name);
    } catch (const std::exception& error) {
      throw std::invalid_argument("parameter " + nh_.resolveName(key) + ": " + error.what());
    }
  }

  template <typename Config>
  void section(const char* key, Config& config) {
    const ros::NodeHandle section_nh(nh_, key);
    RosParameterReader reader(section_nh);
    visitParameters(config, reader);
    validateSection(section_nh, config);
  }

 private:
  const ros::NodeHandle& nh_;
};

}  // namespace

TrackerConfig readTrackerConfig(const ros::NodeHandle& private_nh) {
  TrackerConfig config;
  RosParameterReader reader(private_nh);
  visitParameters(config, reader);
  validateSection(private_nh, config);
  applyImuNoiseFile(config);  // ~ekf/imu_noise_file: Q from the IMU's datasheet figures
  return config;
}

TrackerNodeSettings readTrackerNodeSettings(const ros::NodeHandle& private_nh) {
  TrackerNodeSettings settings;
  RosParameterReader reader(private_nh);
  visitParameters(settings, reader);
  validateSection(private_nh, settings);
  return settings;
}

}  // namespace vicc_tracking
