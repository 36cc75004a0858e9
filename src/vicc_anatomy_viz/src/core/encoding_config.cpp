#include "vicc_anatomy_viz/encoding_config.hpp"

#include <cmath>
#include <set>

#include "vicc_anatomy_viz/errors.hpp"
#include "yaml_reading.hpp"

namespace vicc_anatomy_viz {

using yaml_reading::Cursor;

namespace {

Domain readDomain(const Cursor& item) {
  Domain domain;
  try {
    domain.type = dataTypeFromString(item.string("data_type"));
  } catch (const ConfigError& e) {
    item.fail(e.what());
  }
  const auto values = item.sequence("domain");
  if (domain.type == DataType::kNumerical) {
    if (values.size() != 2) item.fail("a numerical domain is [min, max]");
    domain.min = values[0].asInt();
    domain.max = values[1].asInt();
  } else {
    for (const auto& value : values) domain.labels.push_back(value.asString());
  }
  return domain;
}

Value readValue(const Cursor& item, const Domain& domain) {
  const auto value = domain.parse(item.asString());
  if (!value) item.fail("'" + item.asString() + "' is not a " + toString(domain.type) + " value");
  return *value;
}

SourceProperty readSource(const Cursor& item, const Domain& property_domain) {
  item.allowOnly({"prop_type", "label", "data_type", "domain", "derive"});
  SourceProperty source;
  source.prop_type = item.string("prop_type");
  source.label = item.string("label", source.prop_type);
  source.domain = readDomain(item);
  const Cursor derive = item.child("derive");
  if (!derive.isMap()) derive.fail("derive maps source values to property values");
  for (const auto& [raw, target] : derive.entries()) {
    source.derive[raw] = readValue(target, property_domain);
  }
  return source;
}

Property readProperty(const Cursor& item) {
  item.allowOnly({"prop_type", "label", "data_type", "domain", "normal", "visual_variable",
                  "levels", "thresholds", "source"});
  Property property;
  property.prop_type = item.string("prop_type");
  property.label = item.string("label", property.prop_type);
  property.domain = readDomain(item);
  for (const auto& value : item.optionalSequence("normal")) {
    property.normal.push_back(readValue(value, property.domain));
  }
  property.visual_variable = item.string("visual_variable");
  property.levels = item.integer("levels", 0);
  for (const auto& threshold : item.optionalSequence("thresholds")) {
    property.thresholds.push_back(threshold.asInt());
  }
  if (item.has("source")) property.source = readSource(item.child("source"), property.domain);
  return property;
}

Category readCategory(const Cursor& item) {
  item.allowOnly({"id", "label", "spatial_ref", "props", "compare_contralateral"});
  Category category;
  category.id = item.string("id");
  category.label = item.string("label", category.id);
  category.spatial_refs = item.strings("spatial_ref");
  category.compare_contralateral = item.boolean("compare_contralateral", false);
  for (const auto& prop : item.sequence("props")) category.props.push_back(readProperty(prop));
  return category;
}

VisualVariable readVariable(const Cursor& item) {
  item.allowOnly({"id", "channel", "range", "saturation", "brightness", "unindicated_saturation",
                  "unindicated_brightness", "levels", "alpha"});
  VisualVariable variable;
  variable.id = item.string("id");
  try {
    variable.channel = channelFromString(item.string("channel"));
  } catch (const ConfigError& e) {
    item.fail(e.what());
  }
  variable.range = item.integer("range", 0);
  auto pair = [&](const std::string& key, double& weak, double& strong) {
    if (!item.has(key)) return;
    const auto values = item.sequence(key);
    if (values.size() != 2) item.fail(key + " is [weakest, strongest]");
    weak = values[0].asDouble();
    strong = values[1].asDouble();
  };
  pair("saturation", variable.saturation_weak, variable.saturation_strong);
  pair("brightness", variable.brightness_weak, variable.brightness_strong);
  pair("alpha", variable.alpha_weak, variable.alpha_strong);
  variable.unindicated_saturation =
      item.number("unindicated_saturation", variable.unindicated_saturation);
  variable.unindicated_brightness =
      item.number("unindicated_brightness", variable.unindicated_brightness);
  for (const auto& level : item.optionalSequence("levels")) {
    level.allowOnly({"frequency", "amplitude"});
    variable.texture_levels.push_back({level.number("frequency"), level.number("amplitude")});
  }
  if (variable.channel == Channel::kTexture && variable.texture_levels.empty()) {
    item.fail("a texture variable lists its levels (frequency, amplitude)");
  }
  if (variable.channel != Channel::kTexture && variable.range < 1) {
    item.fail("range (number of distinguishable values) must be at least 1");
  }
  return variable;
}

View readView(const Cursor& item) {
  item.allowOnly({"id", "label", "categories"});
  View view;
  view.id = item.string("id");
  view.label = item.string("label", view.id);
  for (const auto& entry : item.sequence("categories")) {
    entry.allowOnly({"category", "hue"});
    view.categories.push_back({entry.string("category"), entry.string("hue")});
  }
  return view;
}

}  // namespace

EncodingConfig EncodingConfig::fromYamlText(const std::string& yaml_text,
                                            const std::string& origin) {
  const Cursor root = yaml_reading::parseText(yaml_text, origin);
  root.allowOnly({"hues", "visual_variables", "categories", "views"});
  EncodingConfig config;
  for (const auto& item : root.sequence("hues")) {
    item.allowOnly({"name", "degrees"});
    config.hues.push_back({item.string("name"), item.number("degrees")});
  }
  for (const auto& item : root.sequence("visual_variables")) {
    config.variables.push_back(readVariable(item));
  }
  for (const auto& item : root.sequence("categories")) {
    config.categories.push_back(readCategory(item));
  }
  for (const auto& item : root.sequence("views")) config.views.push_back(readView(item));
  return config;
}

EncodingConfig EncodingConfig::load(const std::string& path) {
  return fromYamlText(yaml_reading::readFile(path), path);
}

const NamedHue* EncodingConfig::hue(const std::string& name) const {
  for (const auto& hue : hues) {
    if (hue.name == name) return &hue;
  }
  return nullptr;
}

const VisualVariable* EncodingConfig::variable(const std::string& id) const {
  for (const auto& variable : variables) {
    if (variable.id == id) return &variable;
  }
  return nullptr;
}

const Category* EncodingConfig::category(const std::string& id) const {
  for (const auto& category : categories) {
    if (category.id == id) return &category;
  }
  return nullptr;
}

const View* EncodingConfig::view(const std::string& id) const {
  for (const auto& view : views) {
    if (view.id == id) return &view;
  }
  return nullptr;
}

namespace {

void checkProperty(const EncodingConfig& config, const Category& category, const Property& prop,
                   std::vector<std::string>& problems) {
  const std::string where = "category '" + category.id + "', property '" + prop.prop_type + "'";
  try {
    prop.domain.validate(where);
  } catch (const ConfigError& e) {
    problems.push_back(e.what());
    return;
  }
  for (const auto& value : prop.normal) {
    if (!prop.domain.contains(value)) {
      problems.push_back(where + ": normal value '" + value.toString() + "' is not in the domain " +
                         prop.domain.describe());
    }
  }
  if (!config.variable(prop.visual_variable)) {
    problems.push_back(where + ": unknown visual variable '" + prop.visual_variable + "'" +
                       (prop.visual_variable == "hue"
                            ? " (hue is the category variable a^c; it encodes categories only)"
                            : ""));
  }
  if (!prop.thresholds.empty() && prop.domain.type != DataType::kNumerical) {
    problems.push_back(where + ": thresholds are for numerical properties only");
  }
  if (!prop.thresholds.empty() && prop.levels != 0 &&
      prop.levels != static_cast<int>(prop.thresholds.size()) + 1) {
    problems.push_back(where + ": levels contradicts the number of thresholds");
  }
  if (prop.levels < 0) problems.push_back(where + ": levels must not be negative");
  if (!prop.source) return;
  const SourceProperty& source = *prop.source;
  try {
    source.domain.validate(where + ", source '" + source.prop_type + "'");
  } catch (const ConfigError& e) {
    problems.push_back(e.what());
    return;
  }
  if (category.property(source.prop_type)) {
    problems.push_back(where + ": source type '" + source.prop_type +
                       "' collides with a property type of the category");
  }
  for (const auto& value : source.domain.values()) {
    if (!source.derive.count(value.toString())) {
      problems.push_back(where + ": source value " + value.toString() + " of '" + source.prop_type +
                         "' has no derived value");
    }
  }
  for (const auto& [raw, derived] : source.derive) {
    const auto parsed = source.domain.parse(raw);
    if (!parsed || !source.domain.contains(*parsed)) {
      problems.push_back(where + ": derive names '" + raw + "', not in the source domain " +
                         source.domain.describe());
    }
    if (!prop.domain.contains(derived)) {
      problems.push_back(where + ": derived value '" + derived.toString() +
                         "' is not in the domain " + prop.domain.describe());
    }
  }
}

}  // namespace

std::vector<std::string> EncodingConfig::structuralProblems(const AnatomyCatalog& anatomy) const {
  std::vector<std::string> problems;
  std::set<std::string> seen;
  for (const auto& hue : hues) {
    if (!seen.insert(hue.name).second) problems.push_back("hue '" + hue.name + "' defined twice");
    if (!(hue.degrees >= 0.0 && hue.degrees < 360.0)) {
      problems.push_back("hue '" + hue.name + "': degrees must be within [0, 360)");
    }
  }
  seen.clear();
  for (const auto& variable : variables) {
    if (!seen.insert(variable.id).second) {
      problems.push_back("visual variable '" + variable.id + "' defined twice");
    }
    try {
      variable.validate();
    } catch (const ConfigError& e) {
      problems.push_back(e.what());
    }
  }
  seen.clear();
  for (const auto& category : categories) {
    const std::string where = "category '" + category.id + "'";
    if (!seen.insert(category.id).second) problems.push_back(where + " is defined twice");
    if (category.spatial_refs.empty()) problems.push_back(where + ": no spatial reference");
    for (const auto& ref : category.spatial_refs) {
      if (!anatomy.structureClass(ref)) {
        problems.push_back(where + ": spatial reference '" + ref +
                           "' is not a structure class of the anatomy catalogue");
      }
    }
    if (category.props.empty()) problems.push_back(where + ": has no properties");
    std::set<std::string> prop_types;
    for (const auto& prop : category.props) {
      // Thesis 4.3.2.1: a property type is unique within a category.
      if (!prop_types.insert(prop.prop_type).second) {
        problems.push_back(where + ": property type '" + prop.prop_type +
                           "' appears twice (a property type is unique within a category)");
        continue;
      }
      checkProperty(*this, category, prop, problems);
    }
  }
  seen.clear();
  for (const auto& view : views) {
    const std::string where = "view '" + view.id + "'";
    if (!seen.insert(view.id).second) problems.push_back(where + " is defined twice");
    if (view.categories.empty()) problems.push_back(where + ": has no categories");
    std::set<std::string> in_view;
    for (const auto& entry : view.categories) {
      // Thesis 4.3.2.1: a category is unique within a view.
      if (!in_view.insert(entry.category).second) {
        problems.push_back(where + ": category '" + entry.category +
                           "' appears twice (a category is unique within a view)");
      }
      if (!category(entry.category)) {
        problems.push_back(where + ": unknown category '" + entry.category + "'");
      }
      if (!hue(entry.hue)) {
        problems.push_back(where + ": category '" + entry.category + "' uses unknown hue '" +
                           entry.hue + "'");
      }
    }
  }
  return problems;
}

}  // namespace vicc_anatomy_viz
