#pragma once
// Codings shared by the FHIR export and import: our code system "<category>.<property>",
// CodeableConcept helpers.

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "vicc_anatomy_viz/encoding_model.hpp"

namespace vicc_anatomy_viz::fhir_codes {

/// The property a code names: "<category>.<prop_type>", where prop_type may be a property's
/// recorded source (e.g. paresis.muscle_strength).
struct CodedProperty {
  const Category* category = nullptr;
  const Domain* domain = nullptr;
  std::string prop_type;
  std::string label;
};

std::optional<CodedProperty> propertyOfCode(const EncodingModel& model, const std::string& code);

nlohmann::json coding(const std::string& system, const std::string& code,
                      const std::string& display);
/// The text of `object[key]`, or `fallback` when it is absent or not text (json::value() would
/// throw type_error for another type).
std::string textOr(const nlohmann::json& object, const std::string& key,
                   const std::string& fallback);
/// The first coding of `system` with a text code, or nullptr.
const nlohmann::json* findCoding(const nlohmann::json& concept_json, const std::string& system);
/// "system|code, system|code" for messages.
std::string describeCodings(const nlohmann::json& concept_json);

}  // namespace vicc_anatomy_viz::fhir_codes
