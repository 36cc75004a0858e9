#include "vicc_fusion/fusion_parameters.hpp"

#include <stdexcept>

#include "vicc_common/yaml_parameters.hpp"
#include "vicc_fusion/fusion_config_yaml.hpp"

namespace vicc_fusion {

void FusionRosSettings::validate() const {
  if (map_frame.empty()) throw std::invalid_argument("fusion: map_frame must not be empty");
  if (!(publish_rate >= 0.0)) throw std::invalid_argument("fusion: publish_rate must be >= 0");
  if (pose_queue_size < 1) throw std::invalid_argument("fusion: pose_queue_size must be >= 1");
}

void readFusionParameters(const std::string& yaml_text, const std::string& source,
                          FusionParameterSet& parameters) {
  const YAML::Node root = vicc_common::parseYamlText(yaml_text, source);
  if (root.IsNull()) return;  // empty file: nothing changes
  if (!root.IsMap()) throw std::invalid_argument(source + ": expected a map of parameters");
  vicc_common::YamlParameterReader reader(root, "", source);
  visitParameters(parameters.tracker.tracker, reader);
  visitParameters(parameters.tracker.node, reader);
  visitParameters(parameters.node, reader);
  visitParameters(parameters.model, reader);
  reader.rejectUnknownKeys();
  try {
    parameters.tracker.tracker.validate();
    parameters.tracker.node.validate();
    parameters.node.validate();
    parameters.model.validate();
  } catch (const std::exception& error) {
    throw std::invalid_argument(source + ": " + error.what());
  }
}

void loadFusionParameters(const std::string& path, FusionParameterSet& parameters) {
  readFusionParameters(vicc_common::readTextFile(path, "parameter file"), path, parameters);
}

}  // namespace vicc_fusion
