#include "vicc_anatomy_viz/encoding_model.hpp"

#include <sstream>

#include "vicc_anatomy_viz/errors.hpp"

namespace vicc_anatomy_viz {

EncodingModel::EncodingModel(EncodingConfig config, AnatomyCatalog anatomy)
    : config_(std::move(config)), anatomy_(std::move(anatomy)) {
  const auto problems = config_.structuralProblems(anatomy_);
  if (!problems.empty()) {
    throw ConfigError("invalid encoding configuration:\n" + joinProblems(problems));
  }
  report_ = checkInjectivity(config_);
  std::vector<std::string> rejected = report_.local_violations;
  rejected.insert(rejected.end(), report_.level_errors.begin(), report_.level_errors.end());
  if (!rejected.empty()) {
    throw ConfigError("encoding configuration rejected:\n" + joinProblems(rejected));
  }
  for (const auto& category : config_.categories) {
    for (const auto& prop : category.props) {
      levels_.emplace(std::make_pair(category.id, prop.prop_type),
                      LevelMapping(category, prop, variableOf(prop)));
    }
  }
}

EncodingModel EncodingModel::load(const std::string& config_path, const std::string& anatomy_path) {
  return EncodingModel(EncodingConfig::load(config_path), AnatomyCatalog::load(anatomy_path));
}

const View& EncodingModel::view(const std::string& id) const {
  if (const View* view = config_.view(id)) return *view;
  std::ostringstream known;
  for (std::size_t i = 0; i < config_.views.size(); ++i) {
    known << (i ? ", " : "") << config_.views[i].id;
  }
  throw ConfigError("unknown view '" + id + "' (known views: " + known.str() + ")");
}

const Category& EncodingModel::category(const std::string& id) const {
  if (const Category* category = config_.category(id)) return *category;
  throw ConfigError("unknown category '" + id + "'");
}

const LevelMapping& EncodingModel::levels(const std::string& category,
                                          const std::string& prop_type) const {
  return levels_.at(std::make_pair(category, prop_type));
}

const VisualVariable& EncodingModel::variableOf(const Property& property) const {
  return *config_.variable(property.visual_variable);
}

const NamedHue& EncodingModel::hueOf(const View& view, const std::string& category) const {
  const NamedHue* hue = config_.hue(view.hueOf(category));
  if (!hue) throw ConfigError("category '" + category + "' is not part of view '" + view.id + "'");
  return *hue;
}

std::vector<std::string> EncodingModel::notes(const View& view) const {
  std::vector<std::string> notes;
  for (const auto& quantization : report_.quantizations) {
    if (view.contains(quantization.category)) notes.push_back(quantization.message);
  }
  for (const auto& conflict : report_.spatial_conflicts) {
    if (conflict.view == view.id) notes.push_back(conflict.message);
  }
  return notes;
}

}  // namespace vicc_anatomy_viz
