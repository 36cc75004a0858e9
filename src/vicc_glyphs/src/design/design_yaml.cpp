#include "design_yaml.hpp"

#include <cmath>

namespace vicc_glyphs::design {

YamlMap::YamlMap(const YAML::Node& node, std::string path, const std::set<std::string>& allowed)
    : node_(node), path_(std::move(path)) {
  if (!node_.IsMap()) throw DesignError((path_.empty() ? "the design" : path_) + " must be a map");
  std::set<std::string> seen;
  for (const auto& entry : node_) {
    const std::string name = entry.first.as<std::string>();
    if (!allowed.count(name)) throw DesignError("unknown key " + key(name));
    // yaml-cpp keeps the first of repeated keys: the second would be silently ignored.
    if (!seen.insert(name).second) throw DesignError("key " + key(name) + " is given twice");
  }
}

std::string YamlMap::key(const std::string& name) const {
  return path_.empty() ? name : path_ + "." + name;
}

YAML::Node YamlMap::node(const std::string& name) const {
  if (!has(name)) throw DesignError("missing key " + key(name));
  return node_[name];
}

std::string YamlMap::text(const std::string& name) const {
  const YAML::Node value = node(name);
  if (!value.IsScalar()) throw DesignError(key(name) + " must be a string");
  return value.as<std::string>();
}

std::string YamlMap::text(const std::string& name, const std::string& fallback) const {
  return has(name) ? text(name) : fallback;
}

double YamlMap::number(const std::string& name) const {
  const YAML::Node value = node(name);
  try {
    if (value.IsScalar()) {
      const double number = value.as<double>();
      if (std::isfinite(number)) return number;
    }
  } catch (const YAML::Exception&) {
  }
  throw DesignError(key(name) + " must be a finite number");
}

double YamlMap::number(const std::string& name, double fallback) const {
  return has(name) ? number(name) : fallback;
}

int YamlMap::integer(const std::string& name, int fallback) const {
  if (!has(name)) return fallback;
  try {
    return node(name).as<int>();
  } catch (const YAML::Exception&) {
    throw DesignError(key(name) + " must be an integer");
  }
}

std::vector<double> YamlMap::numbers(const std::string& name) const {
  const YAML::Node value = node(name);
  if (!value.IsSequence()) throw DesignError(key(name) + " must be a list of numbers");
  std::vector<double> result;
  for (size_t i = 0; i < value.size(); ++i) {
    try {
      result.push_back(value[i].as<double>());
    } catch (const YAML::Exception&) {
      throw DesignError(key(name) + "[" + std::to_string(i) + "] must be a number");
    }
    if (!std::isfinite(result.back())) {
      throw DesignError(key(name) + "[" + std::to_string(i) + "] must be finite");
    }
  }
  return result;
}

std::vector<int> YamlMap::integers(const std::string& name) const {
  const YAML::Node value = node(name);
  if (!value.IsSequence()) throw DesignError(key(name) + " must be a list of integers");
  std::vector<int> result;
  for (size_t i = 0; i < value.size(); ++i) {
    try {
      result.push_back(value[i].as<int>());
    } catch (const YAML::Exception&) {
      throw DesignError(key(name) + "[" + std::to_string(i) + "] must be an integer");
    }
  }
  return result;
}

Color YamlMap::color(const std::string& name) const { return parseHexColor(text(name), key(name)); }

std::vector<Color> YamlMap::colors(const std::string& name) const {
  const YAML::Node value = node(name);
  if (!value.IsSequence()) throw DesignError(key(name) + " must be a list of RRGGBB colours");
  std::vector<Color> result;
  for (size_t i = 0; i < value.size(); ++i) {
    const std::string item = key(name) + "[" + std::to_string(i) + "]";
    if (!value[i].IsScalar()) throw DesignError(item + " must be an RRGGBB colour");
    result.push_back(parseHexColor(value[i].as<std::string>(), item));
  }
  return result;
}

Color parseHexColor(const std::string& text, const std::string& key) {
  const std::string hex = !text.empty() && text[0] == '#' ? text.substr(1) : text;
  if (hex.size() != 6 || hex.find_first_not_of("0123456789abcdefABCDEF") != std::string::npos) {
    throw DesignError(key + " must be an RRGGBB colour, got '" + text + "'");
  }
  Color color;
  for (int c = 0; c < 3; ++c) color[c] = std::stoi(hex.substr(2 * c, 2), nullptr, 16) / 255.0;
  return color;
}

}  // namespace vicc_glyphs::design
