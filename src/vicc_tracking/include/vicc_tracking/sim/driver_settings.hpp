#pragma once
// Parameters of the simulated drivers (depth_publisher, imu_publisher nodes): plain data with
// validate() and one (key, field) table each, read by vicc_common's ROS reader (wrong types
// and typos named, no silent defaults).

#include <stdexcept>
#include <string>
#include <type_traits>

namespace vicc_tracking::sim {

/// What both drivers read: the scenario they play.
struct DriverSettings {
  std::string scenario;  ///< a scenario name such as 'hen' or a YAML file; required
  bool loop = false;     ///< start the scenario over when it ends
  void validate() const {
    if (scenario.empty()) {
      throw std::invalid_argument(
          "scenario is required (a scenario name such as 'hen' or a YAML file)");
    }
  }
};

struct DepthDriverSettings {
  DriverSettings driver;
  bool publish_ground_truth = true;  ///< map -> <camera frame>_gt on tf, ground_truth/path
  void validate() const { driver.validate(); }
};

template <typename Config, typename Visitor>
std::enable_if_t<std::is_same_v<std::remove_const_t<Config>, DriverSettings>> visitParameters(
    Config& config, Visitor& visit) {
  visit("scenario", config.scenario);
  visit("loop", config.loop);
}

/// The depth driver's keys: the common ones at the same level, then its own.
template <typename Config, typename Visitor>
std::enable_if_t<std::is_same_v<std::remove_const_t<Config>, DepthDriverSettings>> visitParameters(
    Config& config, Visitor& visit) {
  visitParameters(config.driver, visit);
  visit("publish_ground_truth", config.publish_ground_truth);
}

}  // namespace vicc_tracking::sim
