#pragma once
// Small typed accessors over yaml-cpp for design files: every error names the key path.

#include <yaml-cpp/yaml.h>

#include <set>
#include <string>
#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"
#include "vicc_glyphs/design/glyph_design.hpp"

namespace vicc_glyphs::design {

class YamlMap {
 public:
  /// Throws DesignError if `node` is not a map or has a key outside `allowed`.
  YamlMap(const YAML::Node& node, std::string path, const std::set<std::string>& allowed);

  std::string key(const std::string& name) const;  ///< the full path of a key
  bool has(const std::string& name) const { return static_cast<bool>(node_[name]); }
  YAML::Node node(const std::string& name) const;  ///< required
  std::string text(const std::string& name) const;
  std::string text(const std::string& name, const std::string& fallback) const;
  double number(const std::string& name) const;
  double number(const std::string& name, double fallback) const;
  int integer(const std::string& name, int fallback) const;
  std::vector<double> numbers(const std::string& name) const;
  std::vector<int> integers(const std::string& name) const;
  Color color(const std::string& name) const;  ///< "RRGGBB" -> [0, 1]
  std::vector<Color> colors(const std::string& name) const;

 private:
  YAML::Node node_;
  std::string path_;
};

/// "RRGGBB" (optionally with '#') as 8-bit / 255; throws DesignError naming `key`.
Color parseHexColor(const std::string& text, const std::string& key);

}  // namespace vicc_glyphs::design
