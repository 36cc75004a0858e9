#include "vicc_tracking/tracker_config_yaml.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace vicc_tracking {
namespace {

template <typename T>
const char* expectedType();
template <>
const char* expectedType<int>() { return "an integer"; }
template <>
const char* expectedType<double>() { return "a number"; }
template <>
const char* expectedType<bool>() { return "true or false"; }
template <>
const char* expectedType<std::string>() { return "a string"; }
template <>
const char* expectedType<std::vector<int>>() { return "a list of integers"; }

std::string describe(const YAML::Node& node) {
  if (node.IsScalar()) return "'" + node.Scalar() + "'";
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a section";
  return "no value";
}

/// Reads the keys of one YAML map through a parameter table; remembers which keys the table
/// knows so that the rest can be rejected.
class YamlReader {
 public:
  YamlReader(const YAML::Node& map, std::string prefix, const std::string& source)
      : map_(map), prefix_(std::move(prefix)), source_(source) {}

  template <typename T>
  void operator()(const char* key, T& field) {
    const YAML::Node value = find(key);
    if (!value) return;
    try {
      field = value.as<T>();
    } catch (const YAML::Exception&) {
      fail(key, std::string("has the wrong type: expected ") + expectedType<T>() + ", got " +
                    describe(value));
    }
  }

  void operator()(const char* key, InitStrategyType& field) {
    std::string name = toString(field);
    (*this)(key, name);
    try {
      field = initStrategyFromString(name);
    } catch (const std::exception& error) {
      fail(key, error.what());
    }
  }

  template <typename Config>
  void section(const char* key, Config& config) {
    const YAML::Node node = find(key);
    if (!node || node.IsNull()) return;  // an empty section keeps the defaults
    if (!node.IsMap()) fail(key, "must be a section of keys, got " + describe(node));
    YamlReader reader(node, path(key) + "/", source_);
    visitParameters(config, reader);
    reader.rejectUnknownKeys();
    try {
      config.validate();
    } catch (const std::exception& error) {
      fail(key, error.what());
    }
  }

  void rejectUnknownKeys() const {
    for (const auto& entry : map_) {
      const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : "?";
      if (known_.count(key) > 0) continue;
      std::string known;
      for (const std::string& name : order_) known += (known.empty() ? "" : ", ") + name;
      fail(key, "unknown key (known here: " + known + ")");
    }
  }

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw std::invalid_argument(source_ + ": " + path(key) + ": " + what);
  }

 private:
  YAML::Node find(const char* key) {
    known_.insert(key);
    order_.push_back(key);
    return map_[key];  // map_ is const: no key is added
  }
  std::string path(const std::string& key) const { return prefix_ + key; }

  const YAML::Node map_;
  std::string prefix_;
  const std::string& source_;
  std::set<std::string> known_;
  std::vector<std::string> order_;
};

/// The shortest text that reads back as the same double.
std::string shortestDouble(double value) {
  char text[64];
  for (int precision = 6; precision <= 17; ++precision) {
    std::snprintf(text, sizeof(text), "%.*g", precision, value);
    if (std::strtod(text, nullptr) == value) break;
  }
  return text;
}

class YamlWriter {
 public:
  explicit YamlWriter(YAML::Emitter& out) : out_(out) {}

  template <typename T>
  void operator()(const char* key, const T& value) {
    out_ << YAML::Key << key << YAML::Value << value;
  }
  void operator()(const char* key, const double& value) {
    out_ << YAML::Key << key << YAML::Value << shortestDouble(value);
  }
  void operator()(const char* key, const std::vector<int>& value) {
    out_ << YAML::Key << key << YAML::Value << YAML::Flow << value;
  }
  void operator()(const char* key, const InitStrategyType& value) {
    out_ << YAML::Key << key << YAML::Value << toString(value);
  }
  template <typename Config>
  void section(const char* key, const Config& config) {
    out_ << YAML::Key << key << YAML::Value << YAML::BeginMap;
    visitParameters(config, *this);
    out_ << YAML::EndMap;
  }

 private:
  YAML::Emitter& out_;
};

YAML::Node loadYaml(const std::string& text, const std::string& source) {
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& error) {
    throw std::invalid_argument(source + ": not valid YAML: " + error.what());
  }
}

std::string readFile(const std::string& path, const std::string& what) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument("cannot read the " + what + " " + path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TrackerParameterSet parseTrackerParameters(const std::string& yaml_text,
                                           const std::string& source) {
  const YAML::Node root = loadYaml(yaml_text, source);
  TrackerParameterSet parameters;
  if (root.IsNull()) return parameters;  // empty file: all defaults
  if (!root.IsMap()) throw std::invalid_argument(source + ": expected a map of parameters");
  YamlReader reader(root, "", source);
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
  return parseTrackerParameters(readFile(path, "parameter file"), path);
}

ImuNoise parseImuNoise(const std::string& yaml_text, const std::string& source) {
  const YAML::Node root = loadYaml(yaml_text, source);
  if (!root.IsMap()) throw std::invalid_argument(source + ": expected a map of IMU noise figures");
  ImuNoise noise;
  YamlReader reader(root, "", source);
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
  return parseImuNoise(readFile(path, "IMU noise file"), path);
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
  YamlWriter writer(out);
  visitParameters(parameters.tracker, writer);
  visitParameters(parameters.node, writer);
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

}  // namespace vicc_tracking
