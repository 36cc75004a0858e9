#include "vicc_anatomy_viz/injectivity.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <sstream>

#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/level_mapping.hpp"

namespace vicc_anatomy_viz {

namespace {

std::string quoteList(const std::vector<std::string>& items) {
  std::ostringstream out;
  for (std::size_t i = 0; i < items.size(); ++i) out << (i ? ", " : "") << "'" << items[i] << "'";
  return out.str();
}

/// Local injectivity of M^c: the categories of one view have distinct hues.
void checkCategoryHues(const View& view, InjectivityReport& report) {
  std::map<std::string, std::vector<std::string>> by_hue;
  for (const auto& entry : view.categories) by_hue[entry.hue].push_back(entry.category);
  for (const auto& [hue, categories] : by_hue) {
    if (categories.size() > 1) {
      report.local_violations.push_back("view '" + view.id + "': categories " +
                                        quoteList(categories) + " are all mapped to hue '" + hue +
                                        "' (M^c must be injective within a view)");
    }
  }
}

/// Local injectivity of M^t: the properties of one category use distinct visual variables,
/// and distinct channels, since a structure shows one intensity and one texture at a time.
void checkPropertyVariables(const EncodingConfig& config, const Category& category,
                            InjectivityReport& report) {
  std::map<std::string, std::vector<std::string>> by_variable;
  std::map<Channel, std::vector<std::string>> by_channel;
  for (const auto& prop : category.props) {
    by_variable[prop.visual_variable].push_back(prop.prop_type);
    const VisualVariable* variable = config.variable(prop.visual_variable);
    if (variable) by_channel[variable->channel].push_back(prop.prop_type);
  }
  for (const auto& [variable, props] : by_variable) {
    if (props.size() > 1) {
      report.local_violations.push_back("category '" + category.id + "': properties " +
                                        quoteList(props) + " are all mapped to visual variable '" +
                                        variable + "' (M^t must be injective within a category)");
    }
  }
  for (const auto& [channel, props] : by_channel) {
    if (props.size() > 1 && by_variable.size() == category.props.size()) {
      report.local_violations.push_back(
          "category '" + category.id + "': properties " + quoteList(props) +
          " use visual variables of the same channel '" + toString(channel) +
          "', which cannot be shown together on one structure");
    }
  }
}

/// Global injectivity across views (categories) and categories (property types).
void checkGlobal(const EncodingConfig& config, InjectivityReport& report) {
  std::map<std::string, std::set<std::string>> hues_of_category;
  std::map<std::string, std::set<std::string>> categories_of_hue;
  for (const auto& view : config.views) {
    for (const auto& entry : view.categories) {
      hues_of_category[entry.category].insert(entry.hue);
      categories_of_hue[entry.hue].insert(entry.category);
    }
  }
  for (const auto& [category, hues] : hues_of_category) {
    if (hues.size() > 1) {
      report.global_warnings.push_back(
          "category '" + category + "' has different hues in different views (" +
          quoteList({hues.begin(), hues.end()}) + "): not globally injective");
    }
  }
  for (const auto& [hue, categories] : categories_of_hue) {
    if (categories.size() > 1) {
      report.global_warnings.push_back(
          "hue '" + hue + "' encodes different categories in " + "different views (" +
          quoteList({categories.begin(), categories.end()}) + "): not globally injective");
    }
  }
  std::map<std::string, std::set<std::string>> variables_of_type;
  std::map<std::string, std::set<std::string>> types_of_variable;
  for (const auto& category : config.categories) {
    for (const auto& prop : category.props) {
      variables_of_type[prop.prop_type].insert(prop.visual_variable);
      types_of_variable[prop.visual_variable].insert(prop.prop_type);
    }
  }
  for (const auto& [type, variables] : variables_of_type) {
    if (variables.size() > 1) {
      report.global_warnings.push_back(
          "property type '" + type + "' is encoded by different visual variables (" +
          quoteList({variables.begin(), variables.end()}) + "): not globally injective");
    }
  }
  for (const auto& [variable, types] : types_of_variable) {
    if (types.size() > 1) {
      report.global_warnings.push_back(
          "visual variable '" + variable + "' encodes different property types (" +
          quoteList({types.begin(), types.end()}) + "): not globally injective");
    }
  }
}

/// Spatial injectivity: categories of one view that can land on the same structure.
void checkSpatial(const EncodingConfig& config, const View& view, InjectivityReport& report) {
  for (std::size_t i = 0; i < view.categories.size(); ++i) {
    for (std::size_t j = i + 1; j < view.categories.size(); ++j) {
      const Category* a = config.category(view.categories[i].category);
      const Category* b = config.category(view.categories[j].category);
      if (!a || !b) continue;
      SpatialConflict conflict;
      for (const auto& ref : a->spatial_refs) {
        if (b->refersTo(ref)) conflict.shared_classes.push_back(ref);
      }
      if (conflict.shared_classes.empty()) continue;
      conflict.view = view.id;
      conflict.category_a = a->id;
      conflict.category_b = b->id;
      conflict.message = "view '" + view.id + "': '" + a->id + "' and '" + b->id +
                         "' both refer to " + quoteList(conflict.shared_classes) +
                         " (spatial injectivity violated): shown alternately where they meet on "
                         "one structure; the category filter selects one";
      report.spatial_conflicts.push_back(conflict);
    }
  }
}

/// Property domain injectivity: more displayed values than visual levels is quantization.
void checkDomains(const EncodingConfig& config, InjectivityReport& report) {
  for (const auto& category : config.categories) {
    for (const auto& prop : category.props) {
      const VisualVariable* variable = config.variable(prop.visual_variable);
      if (!variable) continue;
      try {
        const LevelMapping levels(category, prop, *variable);
        if (!levels.quantized()) continue;
        QuantizationReport quantization;
        quantization.category = category.id;
        quantization.prop_type = prop.prop_type;
        quantization.visual_variable = variable->id;
        quantization.values = levels.displayedValueCount();
        quantization.levels = levels.levelCount();
        std::ostringstream message;
        message << "category '" << category.id << "', property '" << prop.prop_type
                << "': " << quantization.values << " values shown with " << quantization.levels
                << " levels of '" << variable->id << "' (quantized:";
        for (int level = 1; level <= levels.levelCount(); ++level) {
          const auto values = levels.valuesAtLevel(level);
          message << (level > 1 ? "," : "") << " " << values.front().toString();
          if (values.size() > 1) message << "-" << values.back().toString();
        }
        message << "); the exact value is in the overlay text";
        quantization.message = message.str();
        report.quantizations.push_back(quantization);
      } catch (const ConfigError& e) {
        report.level_errors.push_back(e.what());
      }
    }
  }
}

}  // namespace

InjectivityReport checkInjectivity(const EncodingConfig& config) {
  InjectivityReport report;
  for (const auto& view : config.views) checkCategoryHues(view, report);
  for (const auto& category : config.categories) checkPropertyVariables(config, category, report);
  checkGlobal(config, report);
  for (const auto& view : config.views) checkSpatial(config, view, report);
  checkDomains(config, report);
  return report;
}

}  // namespace vicc_anatomy_viz
