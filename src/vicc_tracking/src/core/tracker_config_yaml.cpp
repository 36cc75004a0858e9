#include "vicc_tracking/tracker_config_yaml.hpp"

#include <stdexcept>

#include "vicc_common/yaml_parameters.hpp"

namespace vicc_tracking {
using vicc_common::YamlParameterReader;
using vicc_common::YamlParameterWriter;

TrackerParameterSet parseTrackerParameters(const std::string& yaml_text,
                                           const std::string& source) {
  const YAML::Node root = vicc_common::parseYamlText(yaml_text, source);
  TrackerParameterSet parameters;
  if (root.IsNull()) return parameters;  // empty file: all defaults
  if (!root.IsMap()) throw std::invalid_argument(source + ": expected a map of parameters");
  YamlParameterReader reader(root, "", source);
  visitParameters(parameters.tracker, reader);
  visitParameters(parameters.node, reader);
  reader.rejectUnknownKeys();
  try {
    parameters.tracker.validate();
    parameters.node.validate();
  } catch (const std::exception& error) {
    throw std::invalid_argument(source + ": " + error.what());
  }
  applyImuNoiseFile(parameters.tracker);
  return parameters;
}

TrackerParameterSet loadTrackerParameters(const std::string& path) {
  return parseTrackerParameters(vicc_common::readTextFile(path, "parameter file"), path);
}

ImuNoise parseImuNoise(const std::string& yaml_text, const std::string& source) {
  const YAML::Node root = vicc_common::parseYamlText(yaml_text, source);
  if (!root.IsMap()) throw std::invalid_argument(source + ": expected a map of IMU noise figures");
  ImuNoise noise;
  YamlParameterReader reader(root, "", source);
  visitParameters(noise, reader);
  reader.rejectUnknownKeys();
  try {
    noise.validate();
  } catch (const std::exception& error) {
    throw std::invalid_argument(source + ": " + error.what());
  }
  return noise;
}

ImuNoise loadImuNoise(const std::string& path) {
  return parseImuNoise(vicc_common::readTextFile(path, "IMU noise file"), path);
}

void applyImuNoiseFile(TrackerConfig& config) {
  if (config.ekf.imu_noise_file.empty()) return;
  const ImuNoise noise = loadImuNoise(config.ekf.imu_noise_file);
  try {
    config.ekf = ekfNoiseFromImu(config.ekf, noise, config.still_phase.duration);
  } catch (const std::exception& error) {
    throw std::invalid_argument(config.ekf.imu_noise_file + ": " + error.what());
  }
}

std::string toYaml(const TrackerParameterSet& parameters) {
  YAML::Emitter out;
  out << YAML::BeginMap;
  YamlParameterWriter writer(out);
  visitParameters(parameters.tracker, writer);
  visitParameters(parameters.node, writer);
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

}  // namespace vicc_tracking
