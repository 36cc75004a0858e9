#pragma once
// The perception model file (config/perception_model.yaml; format described there): reading
// with errors that name the key, and writing (the fitting tool's output).

#include <stdexcept>
#include <string>

#include "vicc_glyphs/perception/perception_model.hpp"

namespace vicc_glyphs::perception {

/// A missing, mistyped or inconsistent entry of a model file; the message names the key.
struct ModelFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Parses a model from YAML text. An optional `expected_levels` per variable is checked
/// against the count the model derives at the reference size.
PerceptionModel parsePerceptionModel(const std::string& yaml_text);
PerceptionModel loadPerceptionModel(const std::string& path);

/// YAML text of `model` (with `expected_levels` = the derived counts) preceded by the
/// comment lines in `header` (each prefixed with "# ").
std::string perceptionModelToYaml(const PerceptionModel& model, const std::string& header = "");
void savePerceptionModel(const PerceptionModel& model, const std::string& path,
                         const std::string& header = "");

}  // namespace vicc_glyphs::perception
