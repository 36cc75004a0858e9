#include "vicc_common/yaml_parameters.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace vicc_common {

YAML::Node parseYamlText(const std::string& text, const std::string& source) {
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& error) {
    throw std::invalid_argument(source + ": not valid YAML: " + error.what());
  }
}

std::string readTextFile(const std::string& path, const std::string& what) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument("cannot read the " + what + " " + path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string describeYamlNode(const YAML::Node& node) {
  if (node.IsScalar()) return "'" + node.Scalar() + "'";
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a section";
  return "no value";
}

std::string shortestDoubleText(double value) {
  char text[64];
  for (int precision = 6; precision <= 17; ++precision) {
    std::snprintf(text, sizeof(text), "%.*g", precision, value);
    if (std::strtod(text, nullptr) == value) break;
  }
  return text;
}

void YamlParameterReader::rejectUnknownKeys() const {
  for (const auto& entry : map_) {
    const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : "?";
    if (known_.count(key) > 0) continue;
    std::string known;
    for (const std::string& name : order_) known += (known.empty() ? "" : ", ") + name;
    fail(key, "unknown key (known here: " + known + ")");
  }
}

void YamlParameterReader::fail(const std::string& key, const std::string& what) const {
  throw std::invalid_argument(source_ + ": " + path(key) + ": " + what);
}

void YamlParameterReader::wrongType(const char* key, const char* expected,
                                    const YAML::Node& value) const {
  fail(key, std::string("has the wrong type: expected ") + expected + ", got " +
                describeYamlNode(value));
}

YAML::Node YamlParameterReader::find(const char* key) {
  if (known_.insert(key).second) order_.push_back(key);
  return map_[key];  // map_ is const: looking up adds no key
}

}  // namespace vicc_common
