#pragma once
// Parameter tables (parameter_types.hpp) read from and written to YAML, without ROS.
// Errors are std::invalid_argument "<source>: <key path>: <problem>", the path joined by '/'
// ("icp/min_inliers: has the wrong type: expected an integer, got 'many'"); unknown keys are
// named with the keys known at that place.

#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "vicc_common/parameter_types.hpp"

namespace vicc_common {

/// YAML::Load that throws std::invalid_argument "<source>: not valid YAML: ...".
YAML::Node parseYamlText(const std::string& text, const std::string& source);
/// The whole file; std::invalid_argument "cannot read the <what> <path>" otherwise.
std::string readTextFile(const std::string& path, const std::string& what);
/// 'value' for a scalar, else "a list", "a section" or "no value": for error messages.
std::string describeYamlNode(const YAML::Node& node);
/// The shortest text that reads back as the same double.
std::string shortestDoubleText(double value);

/// Reads the keys of one YAML map through parameter tables; several tables may share the map.
/// Call rejectUnknownKeys() after the last table.
class YamlParameterReader {
 public:
  YamlParameterReader(const YAML::Node& map, std::string prefix, std::string source)
      : map_(map), prefix_(std::move(prefix)), source_(std::move(source)) {}

  template <typename T>
  void operator()(const char* key, T& field) {
    const YAML::Node value = find(key);
    if (!value) return;
    if constexpr (IsPlainParameter<T>::value) {
      field = convert<T>(key, value);
    } else {
      const std::string text = convert<std::string>(key, value);
      try {
        fromParameterText(text, field);
      } catch (const std::exception& error) {
        fail(key, error.what());
      }
    }
  }

  /// A nested map; left out or empty keeps the defaults. Validated after reading.
  template <typename Config>
  void section(const char* key, Config& config) {
    const YAML::Node node = find(key);
    if (!node || node.IsNull()) return;
    if (!node.IsMap()) fail(key, "must be a section of keys, got " + describeYamlNode(node));
    YamlParameterReader reader(node, path(key) + "/", source_);
    visitParameters(config, reader);
    reader.rejectUnknownKeys();
    try {
      validateIfDefined(config);
    } catch (const std::exception& error) {
      fail(key, error.what());
    }
  }

  /// Throws for the first key of the map no table asked for.
  void rejectUnknownKeys() const;
  [[noreturn]] void fail(const std::string& key, const std::string& what) const;

 private:
  template <typename T>
  T convert(const char* key, const YAML::Node& value) const {
    // yaml-cpp reads 'yes' or '1' as a bool and any scalar as a string; a list or a section
    // is never a scalar's value.
    if constexpr (std::is_same_v<T, std::string>) {
      if (!value.IsScalar()) wrongType(key, expectedTypeName<T>(), value);
    }
    try {
      return value.as<T>();
    } catch (const YAML::Exception&) {
      wrongType(key, expectedTypeName<T>(), value);
    }
  }
  [[noreturn]] void wrongType(const char* key, const char* expected, const YAML::Node& value) const;
  YAML::Node find(const char* key);
  std::string path(const std::string& key) const { return prefix_ + key; }

  const YAML::Node map_;
  std::string prefix_;
  std::string source_;
  std::set<std::string> known_;
  std::vector<std::string> order_;
};

/// Writes tables as a YAML map that YamlParameterReader reads back unchanged.
class YamlParameterWriter {
 public:
  explicit YamlParameterWriter(YAML::Emitter& out) : out_(out) {}

  template <typename T>
  void operator()(const char* key, const T& value) {
    out_ << YAML::Key << key << YAML::Value;
    if constexpr (std::is_same_v<T, double>) {
      out_ << shortestDoubleText(value);
    } else if constexpr (std::is_same_v<T, std::vector<double>>) {
      out_ << YAML::Flow << YAML::BeginSeq;
      for (const double element : value) out_ << shortestDoubleText(element);
      out_ << YAML::EndSeq;
    } else if constexpr (std::is_same_v<T, std::vector<int>> ||
                         std::is_same_v<T, std::vector<std::string>>) {
      out_ << YAML::Flow << value;
    } else if constexpr (IsPlainParameter<T>::value) {
      out_ << value;
    } else {
      out_ << toParameterText(value);
    }
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

/// One table at the top level of YAML text: keys left out keep their defaults, unknown keys,
/// wrong types and what validate() rejects throw, naming `source` and the key.
template <typename Config>
Config parseYamlParameters(const std::string& text, const std::string& source) {
  const YAML::Node root = parseYamlText(text, source);
  Config config;
  if (root.IsNull()) return config;
  if (!root.IsMap()) throw std::invalid_argument(source + ": expected a map of parameters");
  YamlParameterReader reader(root, "", source);
  visitParameters(config, reader);
  reader.rejectUnknownKeys();
  try {
    validateIfDefined(config);
  } catch (const std::exception& error) {
    throw std::invalid_argument(source + ": " + error.what());
  }
  return config;
}

/// parseYamlParameters() of a file; the messages name the file.
template <typename Config>
Config loadYamlParameters(const std::string& path) {
  return parseYamlParameters<Config>(readTextFile(path, "parameter file"), path);
}

/// The table with every key, in table order.
template <typename Config>
std::string toYamlParameters(const Config& config) {
  YAML::Emitter out;
  out << YAML::BeginMap;
  YamlParameterWriter writer(out);
  visitParameters(config, writer);
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

}  // namespace vicc_common
