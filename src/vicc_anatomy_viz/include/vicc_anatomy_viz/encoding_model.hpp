#pragma once
// A validated encoding configuration together with the anatomy catalogue: the object the
// validator and the encoder work with. Construction rejects any configuration that breaks
// the uniqueness rules or local injectivity, naming the offending entries.

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "vicc_anatomy_viz/anatomy_catalog.hpp"
#include "vicc_anatomy_viz/encoding_config.hpp"
#include "vicc_anatomy_viz/injectivity.hpp"
#include "vicc_anatomy_viz/level_mapping.hpp"

namespace vicc_anatomy_viz {

class EncodingModel {
 public:
  EncodingModel(EncodingConfig config, AnatomyCatalog anatomy);
  static EncodingModel load(const std::string& config_path, const std::string& anatomy_path);

  const EncodingConfig& config() const { return config_; }
  const AnatomyCatalog& anatomy() const { return anatomy_; }
  const InjectivityReport& report() const { return report_; }

  /// Throws ConfigError listing the known views when `id` is unknown.
  const View& view(const std::string& id) const;
  const Category& category(const std::string& id) const;
  const LevelMapping& levels(const std::string& category, const std::string& prop_type) const;
  const VisualVariable& variableOf(const Property& property) const;
  const NamedHue& hueOf(const View& view, const std::string& category) const;
  /// Quantization and spatial-conflict reports relevant to one view.
  std::vector<std::string> notes(const View& view) const;

 private:
  EncodingConfig config_;
  AnatomyCatalog anatomy_;
  InjectivityReport report_;
  std::map<std::pair<std::string, std::string>, LevelMapping> levels_;
};

}  // namespace vicc_anatomy_viz
