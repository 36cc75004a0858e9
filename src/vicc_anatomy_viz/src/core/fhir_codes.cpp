#include "fhir_codes.hpp"

namespace vicc_anatomy_viz::fhir_codes {

using nlohmann::json;

std::optional<CodedProperty> propertyOfCode(const EncodingModel& model, const std::string& code) {
  const auto dot = code.find('.');
  if (dot == std::string::npos) return std::nullopt;
  CodedProperty coded;
  coded.category = model.config().category(code.substr(0, dot));
  coded.prop_type = code.substr(dot + 1);
  if (!coded.category) return std::nullopt;
  if (const Property* prop = coded.category->property(coded.prop_type)) {
    coded.domain = &prop->domain;
    coded.label = prop->label;
  } else if (const Property* derived = coded.category->propertyWithSource(coded.prop_type)) {
    coded.domain = &derived->source->domain;
    coded.label = derived->source->label;
  } else {
    return std::nullopt;
  }
  return coded;
}

std::string textOr(const json& object, const std::string& key, const std::string& fallback) {
  if (!object.is_object()) return fallback;
  const auto it = object.find(key);
  return it != object.end() && it->is_string() ? it->get<std::string>() : fallback;
}

json coding(const std::string& system, const std::string& code, const std::string& display) {
  json out = {{"system", system}, {"code", code}};
  if (!display.empty()) out["display"] = display;
  return out;
}

const json* findCoding(const json& concept_json, const std::string& system) {
  if (!concept_json.is_object() || !concept_json.contains("coding") ||
      !concept_json["coding"].is_array()) {
    return nullptr;
  }
  for (const auto& c : concept_json["coding"]) {
    if (c.is_object() && textOr(c, "system", "") == system && c.contains("code") &&
        c["code"].is_string()) {
      return &c;
    }
  }
  return nullptr;
}

std::string describeCodings(const json& concept_json) {
  std::string out;
  if (concept_json.is_object() && concept_json.contains("coding") &&
      concept_json["coding"].is_array()) {
    for (const auto& c : concept_json["coding"]) {
      if (!out.empty()) out += ", ";
      out += textOr(c, "system", "?") + "|" + textOr(c, "code", "?");
    }
  }
  return out.empty() ? "(no coding)" : out;
}

}  // namespace vicc_anatomy_viz::fhir_codes
