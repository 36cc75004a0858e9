#pragma once
// The view configuration as written in YAML: hues, visual variables, categories and views.
// Parsing checks types; structuralProblems() checks the uniqueness rules of thesis 4.3.2.1
// and that every reference (hue, variable, structure class, category) resolves.

#include <string>
#include <vector>

#include "vicc_anatomy_viz/anatomy_catalog.hpp"
#include "vicc_anatomy_viz/data_model.hpp"
#include "vicc_anatomy_viz/visual_variables.hpp"

namespace vicc_anatomy_viz {

struct EncodingConfig {
  std::vector<NamedHue> hues;             ///< the range of the category variable a^c
  std::vector<VisualVariable> variables;  ///< A \ {a^c}
  std::vector<Category> categories;       ///< C
  std::vector<View> views;                ///< the views, each with its M^c

  /// Throws ConfigError (with file and line where known) on malformed YAML or wrong types.
  static EncodingConfig fromYamlText(const std::string& yaml_text, const std::string& origin);
  static EncodingConfig load(const std::string& path);

  const NamedHue* hue(const std::string& name) const;
  const VisualVariable* variable(const std::string& id) const;
  const Category* category(const std::string& id) const;
  const View* view(const std::string& id) const;

  /// Violations of the uniqueness rules (property type unique within a category, category
  /// unique within a view, unique ids) and unresolved references; empty when sound.
  std::vector<std::string> structuralProblems(const AnatomyCatalog& anatomy) const;
};

}  // namespace vicc_anatomy_viz
