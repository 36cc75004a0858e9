#include "vicc_anatomy_viz/fhir_bundle.hpp"

#include <cmath>
#include <cstdio>
#include <map>
#include <tuple>

#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/time_format.hpp"

namespace vicc_anatomy_viz {

using nlohmann::json;

namespace {

/// Stable resource ids, so that exporting twice gives the same Bundle.
std::string resourceId(const std::string& key) {
  std::uint64_t hash = 1469598103934665603ULL;  // FNV-1a
  for (const unsigned char c : key) {
    hash ^= c;
    hash *= 1099511628211ULL;
  }
  char buffer[24];
  std::snprintf(buffer, sizeof(buffer), "vicc-%016llx", static_cast<unsigned long long>(hash));
  return buffer;
}

json coding(const std::string& system, const std::string& code, const std::string& display) {
  json out = {{"system", system}, {"code", code}};
  if (!display.empty()) out["display"] = display;
  return out;
}

/// The property a code names: "<category>.<prop_type>" where prop_type may be a property's
/// recorded source (e.g. paresis.muscle_strength).
struct CodedProperty {
  const Category* category = nullptr;
  const Domain* domain = nullptr;
  std::string prop_type;
  std::string label;
};

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

json valueElement(const Domain& domain, const Value& value) {
  if (value.isNumber()) return {{"valueInteger", value.asNumber()}};
  if (domain.isBinary()) return {{"valueBoolean", value.asLabel() == "true"}};
  return {{"valueCodeableConcept", {{"coding", json::array({coding(fhir::kValueSystem,
                                                                   value.asLabel(), "")})}}}};
}

std::string describeCodings(const json& concept_json) {
  std::string out;
  if (concept_json.is_object() && concept_json.contains("coding") && concept_json["coding"].is_array()) {
    for (const auto& c : concept_json["coding"]) {
      if (!out.empty()) out += ", ";
      out += c.value("system", std::string("?")) + "|" + c.value("code", std::string("?"));
    }
  }
  return out.empty() ? "(no coding)" : out;
}

const json* findCoding(const json& concept_json, const std::string& system) {
  if (!concept_json.is_object() || !concept_json.contains("coding") ||
      !concept_json["coding"].is_array()) {
    return nullptr;
  }
  for (const auto& c : concept_json["coding"]) {
    if (c.is_object() && c.value("system", std::string()) == system && c.contains("code") &&
        c["code"].is_string()) {
      return &c;
    }
  }
  return nullptr;
}

std::optional<Side> sideOfSnomed(const json& concept_json) {
  const json* c = findCoding(concept_json, fhir::kSnomed);
  if (!c) return std::nullopt;
  const std::string code = (*c)["code"].get<std::string>();
  if (code == fhir::kSnomedLeft) return Side::kLeft;
  if (code == fhir::kSnomedRight) return Side::kRight;
  return std::nullopt;
}

}  // namespace

bool isFhirBundle(const json& document) {
  return document.is_object() && document.value("resourceType", std::string()) == "Bundle";
}

json examinationsToFhirBundle(const std::vector<Examination>& examinations,
                              const EncodingModel& model) {
  json entries = json::array();
  const AnatomyCatalog& anatomy = model.anatomy();
  for (const auto& examination : examinations) {
    const std::string when = formatTimestamp(examination.taken_at);
    for (const auto& finding : examination.findings) {
      const Structure* structure = anatomy.structure(finding.structure);
      for (const auto& [prop_type, value] : finding.values) {
        const auto coded = propertyOfCode(model, finding.category + "." + prop_type);
        if (!coded || !structure) continue;  // stored data was validated; cannot happen
        const std::string code = finding.category + "." + prop_type;
        json body_site = {{"coding", json::array({coding(fhir::kAnatomySystem, structure->id,
                                                         structure->name)})},
                          {"text", anatomy.displayName(*structure, finding.side)}};
        if (!structure->fma_id.empty()) {
          body_site["coding"].push_back(
              coding(fhir::kFmaSystem, structure->fma_id.substr(4), structure->name));
        }
        if (finding.side != Side::kNone) {
          const bool left = finding.side == Side::kLeft;
          body_site["extension"] = json::array(
              {{{"url", fhir::kLateralityExtension},
                {"valueCodeableConcept",
                 {{"coding", json::array({coding(fhir::kSnomed,
                                                 left ? fhir::kSnomedLeft : fhir::kSnomedRight,
                                                 left ? "Left" : "Right")})}}}}});
        }
        json observation = {
            {"resourceType", "Observation"},
            {"id", resourceId(examination.patient_id + "|" + when + "|" + code + "|" +
                              finding.structure + "|" + toString(finding.side))},
            {"status", "final"},
            {"category",
             json::array({{{"coding", json::array({coding(
                                          "http://terminology.hl7.org/CodeSystem/"
                                          "observation-category",
                                          "exam", "Exam")})}}})},
            {"code",
             {{"coding", json::array({coding(fhir::kCodeSystem, code,
                                             coded->category->label + " " + coded->label)})}}},
            {"subject",
             {{"identifier", {{"system", fhir::kPseudonymSystem},
                              {"value", examination.patient_id}}}}},
            {"effectiveDateTime", when},
            {"bodySite", body_site}};
        observation.update(valueElement(*coded->domain, value));
        entries.push_back({{"fullUrl", "urn:uuid:" + observation["id"].get<std::string>()},
                           {"resource", observation}});
      }
    }
  }
  return {{"resourceType", "Bundle"}, {"type", "collection"}, {"entry", entries}};
}

FhirImport examinationsFromFhirBundle(const json& bundle, const EncodingModel& model,
                                      const FhirImportOptions& options) {
  if (!isFhirBundle(bundle)) throw ExchangeError("not a FHIR Bundle (resourceType != Bundle)");
  FhirImport result;
  std::vector<std::string> problems;
  auto unknown = [&](const std::string& message) {
    if (options.skip_unknown) {
      result.warnings.push_back(message + " (skipped)");
    } else {
      problems.push_back(message);
    }
  };
  using FindingKey = std::tuple<std::string, std::string, Side>;
  std::map<std::pair<std::string, std::int64_t>, std::map<FindingKey, Finding>> grouped;
  std::map<std::tuple<std::string, std::int64_t, std::string, std::string, Side, std::string>,
           std::size_t>
      seen;
  const json entries = bundle.value("entry", json::array());
  if (!entries.is_array()) throw ExchangeError("Bundle.entry must be a list");
  const AnatomyCatalog& anatomy = model.anatomy();

  for (std::size_t i = 0; i < entries.size(); ++i) {
    const json& resource = entries[i].is_object() ? entries[i].value("resource", json()) : json();
    const std::string type = resource.is_object() ? resource.value("resourceType", "") : "";
    if (type != "Observation") {
      // Other resources (Patient, Encounter, ...) may carry names: only the type is reported.
      result.warnings.push_back("entry " + std::to_string(i) + ": " +
                                (type.empty() ? std::string("entry without a resource")
                                              : type + " resource") +
                                " ignored (only Observation is imported)");
      continue;
    }
    const std::string where =
        "entry " + std::to_string(i) + " (Observation " + resource.value("id", "?") + ")";
    const std::string status = resource.value("status", "");
    if (status == "entered-in-error" || status == "cancelled") {
      result.warnings.push_back(where + ": status '" + status + "', not imported");
      continue;
    }
    if (status != "final" && status != "amended" && status != "corrected" &&
        status != "preliminary") {
      problems.push_back(where + ": status '" + status +
                         "' (expected final, amended, corrected or preliminary)");
      continue;
    }
    const json code = resource.value("code", json());
    const json* our_code = findCoding(code, fhir::kCodeSystem);
    const auto coded = our_code ? propertyOfCode(model, (*our_code)["code"].get<std::string>())
                                : std::nullopt;
    if (!coded) {
      unknown(where + ": unknown code " + describeCodings(code));
      continue;
    }
    std::string patient;
    const json subject = resource.value("subject", json());
    if (subject.is_object() && subject.contains("identifier") &&
        subject["identifier"].is_object() && subject["identifier"].contains("value") &&
        subject["identifier"]["value"].is_string()) {
      patient = subject["identifier"]["value"].get<std::string>();
    } else if (subject.is_object() && subject.value("reference", "").rfind("Patient/", 0) == 0) {
      patient = subject["reference"].get<std::string>().substr(8);
    }
    if (patient.empty()) {
      problems.push_back(where + ": subject has no pseudonym identifier or Patient reference");
      continue;
    }
    if (const std::string reason = patientIdProblem(patient); !reason.empty()) {
      problems.push_back(where + ": subject: " + reason);
      continue;
    }
    const std::string when_text = resource.value("effectiveDateTime", "");
    const auto when = parseTimestamp(when_text);
    if (!when) {
      problems.push_back(where + ": effectiveDateTime '" + when_text +
                         "' missing or not an ISO 8601 date-time");
      continue;
    }
    const json body_site = resource.value("bodySite", json());
    const Structure* structure = nullptr;
    if (const json* c = findCoding(body_site, fhir::kAnatomySystem)) {
      structure = anatomy.structure((*c)["code"].get<std::string>());
    } else if (const json* fma = findCoding(body_site, fhir::kFmaSystem)) {
      structure = anatomy.structureByFmaId("FMA:" + (*fma)["code"].get<std::string>());
    }
    if (!structure) {
      unknown(where + ": unknown body site " + describeCodings(body_site));
      continue;
    }
    std::optional<Side> side;
    bool laterality_given = false;
    if (body_site.is_object() && body_site.contains("extension") &&
        body_site["extension"].is_array()) {
      for (const auto& extension : body_site["extension"]) {
        if (extension.value("url", "") != fhir::kLateralityExtension) continue;
        laterality_given = true;
        side = sideOfSnomed(extension.value("valueCodeableConcept", json()));
      }
    }
    if (!laterality_given && findCoding(body_site, fhir::kSnomed)) {
      laterality_given = true;
      side = sideOfSnomed(body_site);
    }
    if (laterality_given && !side) {
      unknown(where + ": laterality is neither SNOMED CT " + fhir::kSnomedLeft + " (left) nor " +
              fhir::kSnomedRight + " (right)");
      continue;
    }
    const Side finding_side = side.value_or(Side::kNone);

    std::optional<Value> value;
    if (resource.contains("valueInteger") && resource["valueInteger"].is_number_integer()) {
      const auto number = resource["valueInteger"].get<long long>();
      if (number < -2147483647LL || number > 2147483647LL) {
        problems.push_back(where + ": valueInteger out of range");
        continue;
      }
      value = Value::number(static_cast<int>(number));
    } else if (resource.contains("valueBoolean") && resource["valueBoolean"].is_boolean()) {
      value = Value::label(resource["valueBoolean"].get<bool>() ? "true" : "false");
    } else if (resource.contains("valueQuantity") && resource["valueQuantity"].is_object() &&
               resource["valueQuantity"].contains("value") &&
               resource["valueQuantity"]["value"].is_number()) {
      const double number = resource["valueQuantity"]["value"].get<double>();
      if (std::floor(number) != number || std::fabs(number) > 1e6) {
        problems.push_back(where + ": valueQuantity " + std::to_string(number) +
                           " is not an integer score");
        continue;
      }
      value = Value::number(static_cast<int>(number));
    } else if (resource.contains("valueCodeableConcept")) {
      const json& concept_json = resource["valueCodeableConcept"];
      if (const json* c = findCoding(concept_json, fhir::kValueSystem)) {
        value = Value::label((*c)["code"].get<std::string>());
      } else {
        unknown(where + ": unknown value code " + describeCodings(concept_json));
        continue;
      }
    }
    if (!value) {
      problems.push_back(where + ": no valueInteger, valueBoolean, valueQuantity or "
                                 "valueCodeableConcept");
      continue;
    }
    const auto key = std::make_tuple(patient, *when, coded->category->id, structure->id,
                                     finding_side, coded->prop_type);
    if (const auto previous = seen.find(key); previous != seen.end()) {
      problems.push_back(where + ": repeats the observation of entry " +
                         std::to_string(previous->second));
      continue;
    }
    seen[key] = i;
    Finding& finding = grouped[{patient, *when}][FindingKey{coded->category->id, structure->id,
                                                            finding_side}];
    finding.category = coded->category->id;
    finding.structure = structure->id;
    finding.side = finding_side;
    finding.values[coded->prop_type] = *value;
  }
  if (!problems.empty()) throw ValidationError(problems);
  for (auto& [exam_key, findings] : grouped) {
    Examination examination;
    examination.patient_id = exam_key.first;
    examination.taken_at = exam_key.second;
    examination.source = "fhir";
    for (auto& [finding_key, finding] : findings) examination.findings.push_back(finding);
    result.examinations.push_back(std::move(examination));
  }
  return result;
}

}  // namespace vicc_anatomy_viz
