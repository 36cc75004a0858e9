// FHIR R4 import: Observations -> examinations (grouped by patient and time) and findings
// (grouped by category, structure and side). Unknown codes are reported, never dropped
// silently.
#include <cmath>
#include <map>
#include <tuple>

#include "fhir_codes.hpp"
#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/fhir_bundle.hpp"
#include "vicc_anatomy_viz/time_format.hpp"

namespace vicc_anatomy_viz {

using fhir_codes::describeCodings;
using fhir_codes::findCoding;
using fhir_codes::textOr;
using nlohmann::json;

namespace {

/// One recorded property value read from an Observation.
struct ObservedValue {
  std::string patient;
  std::int64_t time = 0;
  std::string category;
  std::string structure;
  Side side = Side::kNone;
  std::string prop_type;
  Value value;
};

/// Collects what cannot be imported: malformed observations always reject the bundle; unknown
/// codes do too unless the caller chose to skip them (then they become warnings).
class ImportReport {
 public:
  ImportReport(bool skip_unknown, std::vector<std::string>& warnings)
      : skip_unknown_(skip_unknown), warnings_(warnings) {}
  void malformed(const std::string& message) { problems_.push_back(message); }
  void unknown(const std::string& message) {
    if (skip_unknown_) {
      warnings_.push_back(message + " (skipped)");
    } else {
      problems_.push_back(message);
    }
  }
  void skipped(const std::string& message) { warnings_.push_back(message); }
  const std::vector<std::string>& problems() const { return problems_; }

 private:
  bool skip_unknown_;
  std::vector<std::string>& warnings_;
  std::vector<std::string> problems_;
};

std::optional<std::string> readSubject(const json& resource, const std::string& where,
                                       ImportReport& report) {
  const json subject = resource.value("subject", json());
  std::string patient;
  if (subject.is_object() && subject.contains("identifier") && subject["identifier"].is_object() &&
      subject["identifier"].contains("value") && subject["identifier"]["value"].is_string()) {
    patient = subject["identifier"]["value"].get<std::string>();
  } else if (subject.is_object() && subject.contains("reference") &&
             subject["reference"].is_string() &&
             subject["reference"].get<std::string>().rfind("Patient/", 0) == 0) {
    patient = subject["reference"].get<std::string>().substr(8);
  }
  if (patient.empty()) {
    report.malformed(where + ": subject has no pseudonym identifier or Patient reference");
    return std::nullopt;
  }
  if (const std::string reason = patientIdProblem(patient); !reason.empty()) {
    report.malformed(where + ": subject: " + reason);
    return std::nullopt;
  }
  return patient;
}

/// Our anatomy code, or else an FMA coding of a catalogued structure.
const Structure* readBodySite(const json& body_site, const AnatomyCatalog& anatomy) {
  if (const json* c = findCoding(body_site, fhir::kAnatomySystem)) {
    return anatomy.structure((*c)["code"].get<std::string>());
  }
  if (const json* fma = findCoding(body_site, fhir::kFmaSystem)) {
    return anatomy.structureByFmaId("FMA:" + (*fma)["code"].get<std::string>());
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

/// The laterality extension, or a SNOMED CT left/right coding in bodySite; none = midline.
/// nullopt when a laterality is given but is neither left nor right.
std::optional<Side> readLaterality(const json& body_site) {
  if (body_site.is_object() && body_site.contains("extension") &&
      body_site["extension"].is_array()) {
    for (const auto& extension : body_site["extension"]) {
      if (extension.is_object() && textOr(extension, "url", "") == fhir::kLateralityExtension) {
        return sideOfSnomed(extension.value("valueCodeableConcept", json()));
      }
    }
  }
  if (findCoding(body_site, fhir::kSnomed)) return sideOfSnomed(body_site);
  return Side::kNone;
}

/// value[x]: valueInteger, valueBoolean, an integral valueQuantity, or a valueCodeableConcept
/// of our value code system.
std::optional<Value> readValue(const json& resource, const std::string& where,
                               ImportReport& report) {
  if (resource.contains("valueInteger") && resource["valueInteger"].is_number_integer()) {
    // get<long long>() would wrap an unsigned number above LLONG_MAX to a negative one.
    const bool too_large = resource["valueInteger"].is_number_unsigned() &&
                           resource["valueInteger"].get<unsigned long long>() > 2147483647ULL;
    const auto number = too_large ? 0LL : resource["valueInteger"].get<long long>();
    if (too_large || number < -2147483647LL || number > 2147483647LL) {
      report.malformed(where + ": valueInteger out of range");
      return std::nullopt;
    }
    return Value::number(static_cast<int>(number));
  }
  if (resource.contains("valueBoolean") && resource["valueBoolean"].is_boolean()) {
    return Value::label(resource["valueBoolean"].get<bool>() ? "true" : "false");
  }
  if (resource.contains("valueQuantity") && resource["valueQuantity"].is_object() &&
      resource["valueQuantity"].contains("value") &&
      resource["valueQuantity"]["value"].is_number()) {
    const double number = resource["valueQuantity"]["value"].get<double>();
    if (std::floor(number) != number || std::fabs(number) > 1e6) {
      report.malformed(where + ": valueQuantity " + resource["valueQuantity"]["value"].dump() +
                       " is not an integer score");
      return std::nullopt;
    }
    return Value::number(static_cast<int>(number));
  }
  if (resource.contains("valueCodeableConcept")) {
    const json& concept_json = resource["valueCodeableConcept"];
    if (const json* c = findCoding(concept_json, fhir::kValueSystem)) {
      return Value::label((*c)["code"].get<std::string>());
    }
    report.unknown(where + ": unknown value code " + describeCodings(concept_json));
    return std::nullopt;
  }
  report.malformed(where +
                   ": no valueInteger, valueBoolean, valueQuantity or valueCodeableConcept");
  return std::nullopt;
}

std::optional<ObservedValue> readObservation(const json& resource, const std::string& where,
                                             const EncodingModel& model, ImportReport& report) {
  const std::string status = textOr(resource, "status", "");
  if (status == "entered-in-error" || status == "cancelled") {
    report.skipped(where + ": status '" + status + "', not imported");
    return std::nullopt;
  }
  if (status != "final" && status != "amended" && status != "corrected" &&
      status != "preliminary") {
    report.malformed(where + ": status '" + status +
                     "' (expected final, amended, corrected or preliminary)");
    return std::nullopt;
  }
  const json code = resource.value("code", json());
  const json* our_code = findCoding(code, fhir::kCodeSystem);
  const auto coded = our_code
                         ? fhir_codes::propertyOfCode(model, (*our_code)["code"].get<std::string>())
                         : std::nullopt;
  if (!coded) {
    report.unknown(where + ": unknown code " + describeCodings(code));
    return std::nullopt;
  }
  const auto patient = readSubject(resource, where, report);
  if (!patient) return std::nullopt;
  const std::string when_text =
      resource.contains("effectiveDateTime") && resource["effectiveDateTime"].is_string()
          ? resource["effectiveDateTime"].get<std::string>()
          : "";
  const auto when = parseTimestamp(when_text);
  if (!when) {
    report.malformed(where + ": effectiveDateTime '" + when_text +
                     "' missing or not an ISO 8601 date-time");
    return std::nullopt;
  }
  const json body_site = resource.value("bodySite", json());
  const Structure* structure = readBodySite(body_site, model.anatomy());
  if (!structure) {
    report.unknown(where + ": unknown body site " + describeCodings(body_site));
    return std::nullopt;
  }
  const auto side = readLaterality(body_site);
  if (!side) {
    report.unknown(where + ": laterality is neither SNOMED CT " + fhir::kSnomedLeft +
                   " (left) nor " + fhir::kSnomedRight + " (right)");
    return std::nullopt;
  }
  const auto value = readValue(resource, where, report);
  if (!value) return std::nullopt;
  return ObservedValue{*patient,         *when, coded->category->id, structure->id, *side,
                       coded->prop_type, *value};
}

}  // namespace

FhirImport examinationsFromFhirBundle(const json& bundle, const EncodingModel& model,
                                      const FhirImportOptions& options) {
  if (!isFhirBundle(bundle)) throw ExchangeError("not a FHIR Bundle (resourceType != Bundle)");
  const json entries = bundle.value("entry", json::array());
  if (!entries.is_array()) throw ExchangeError("Bundle.entry must be a list");
  FhirImport result;
  ImportReport report(options.skip_unknown, result.warnings);
  using ExaminationKey = std::pair<std::string, std::int64_t>;
  using FindingKey = std::tuple<std::string, std::string, Side>;
  std::map<ExaminationKey, std::map<FindingKey, Finding>> grouped;
  std::map<std::tuple<ExaminationKey, FindingKey, std::string>, std::size_t> first_entry;

  for (std::size_t i = 0; i < entries.size(); ++i) {
    const json resource = entries[i].is_object() ? entries[i].value("resource", json()) : json();
    const std::string type = textOr(resource, "resourceType", "");
    if (type != "Observation") {
      // Other resources (Patient, Encounter, ...) may carry names: only the type is reported.
      report.skipped("entry " + std::to_string(i) + ": " +
                     (type.empty() ? std::string("entry without a resource") : type + " resource") +
                     " ignored (only Observation is imported)");
      continue;
    }
    const std::string where =
        "entry " + std::to_string(i) + " (Observation " + textOr(resource, "id", "?") + ")";
    const auto observed = readObservation(resource, where, model, report);
    if (!observed) continue;
    const ExaminationKey examination{observed->patient, observed->time};
    const FindingKey finding_key{observed->category, observed->structure, observed->side};
    const auto key = std::make_tuple(examination, finding_key, observed->prop_type);
    if (const auto previous = first_entry.find(key); previous != first_entry.end()) {
      report.malformed(where + ": repeats the observation of entry " +
                       std::to_string(previous->second));
      continue;
    }
    first_entry[key] = i;
    Finding& finding = grouped[examination][finding_key];
    finding.category = observed->category;
    finding.structure = observed->structure;
    finding.side = observed->side;
    finding.values[observed->prop_type] = observed->value;
  }
  if (!report.problems().empty()) throw ValidationError(report.problems());
  for (auto& [key, findings] : grouped) {
    Examination examination;
    examination.patient_id = key.first;
    examination.taken_at = key.second;
    examination.source = "fhir";
    for (auto& [finding_key, finding] : findings) examination.findings.push_back(finding);
    result.examinations.push_back(std::move(examination));
  }
  return result;
}

}  // namespace vicc_anatomy_viz
