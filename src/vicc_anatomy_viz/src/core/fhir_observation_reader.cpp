#include "fhir_observation_reader.hpp"

#include <cmath>
#include <set>

#include "fhir_codes.hpp"

namespace vicc_anatomy_viz::fhir_import {

using fhir_codes::describeCodings;
using fhir_codes::findCoding;
using nlohmann::json;

bool ImportReport::unknown(const std::string& message) {
  if (!skip_unknown_) {
    problems_.push_back(message);
    return false;
  }
  warnings_.push_back(message + " (skipped; the examination is stored as partial)");
  return true;
}

namespace {

constexpr const char* kUcum = "http://unitsofmeasure.org";

/// Every modifierExtension url anywhere in the resource (FHIR: a resource with a modifier
/// that is not understood must not be processed).
void collectModifiers(const json& node, std::vector<std::string>& urls) {
  if (node.is_array()) {
    for (const auto& item : node) collectModifiers(item, urls);
    return;
  }
  if (!node.is_object()) return;
  for (const auto& [key, child] : node.items()) {
    if (key == "modifierExtension") {
      if (!child.is_array()) {
        urls.push_back("(malformed)");
        continue;
      }
      for (const auto& extension : child) {
        urls.push_back(extension.is_object() ? fhir_codes::textOr(extension, "url", "(no url)")
                                             : std::string("(malformed)"));
      }
    }
    collectModifiers(child, urls);
  }
}

/// All codings of `system` in a CodeableConcept (text codes only).
std::vector<std::string> codesOf(const json& concept_json, const std::string& system) {
  std::vector<std::string> codes;
  if (!concept_json.is_object() || !concept_json.contains("coding") ||
      !concept_json["coding"].is_array()) {
    return codes;
  }
  for (const auto& c : concept_json["coding"]) {
    if (c.is_object() && fhir_codes::textOr(c, "system", "") == system && c.contains("code") &&
        c["code"].is_string()) {
      codes.push_back(c["code"].get<std::string>());
    }
  }
  return codes;
}

bool readStatus(const json& resource, ObservationEntry& entry, ImportReport& report) {
  const json status_json = resource.value("status", json());
  const std::string status = status_json.is_string() ? status_json.get<std::string>() : "";
  if (status == "entered-in-error" || status == "cancelled") {
    report.warn(entry.where + ": status '" + status + "', not imported");
    return false;
  }
  if (status == "preliminary") {
    entry.status = ExaminationStatus::kPreliminary;
  } else if (status != "final" && status != "amended" && status != "corrected") {
    report.malformed(entry.where + ": status '" + status +
                     "' (expected final, amended, corrected or preliminary)");
    return false;
  }
  return true;
}

/// Only our pseudonym identifier system: an MRN or another system's id is not a pseudonym.
bool readSubject(const json& resource, ObservationEntry& entry, ImportReport& report) {
  const json subject = resource.value("subject", json());
  const json identifier = subject.is_object() ? subject.value("identifier", json()) : json();
  if (!identifier.is_object() || !identifier.contains("value") ||
      !identifier["value"].is_string()) {
    report.malformed(entry.where + ": subject has no identifier of the pseudonym system " +
                     fhir::kPseudonymSystem);
    return false;
  }
  const std::string system = fhir_codes::textOr(identifier, "system", "");
  if (system != fhir::kPseudonymSystem) {
    report.malformed(entry.where + ": subject identifier of system '" + system +
                     "' is not a pseudonym (expected " + fhir::kPseudonymSystem + ")");
    return false;
  }
  entry.patient = identifier["value"].get<std::string>();
  if (const std::string reason = patientIdProblem(entry.patient); !reason.empty()) {
    report.malformed(entry.where + ": subject: " + reason);
    return false;
  }
  return true;
}

bool readTime(const json& resource, ObservationEntry& entry, const TimePlausibility& plausibility,
              ImportReport& report) {
  const json effective = resource.value("effectiveDateTime", json());
  const std::string text = effective.is_string() ? effective.get<std::string>() : "";
  std::string why = "missing";
  const auto parsed = text.empty() ? std::nullopt : parseTime(text, &why);
  if (!parsed) {
    report.malformed(entry.where + ": effectiveDateTime '" + text + "': " + why);
    return false;
  }
  if (const std::string problem = plausibility.problem(parsed->us); !problem.empty()) {
    report.malformed(entry.where + ": implausible effectiveDateTime: " + problem);
    return false;
  }
  if (!parsed->has_offset && !parsed->date_only) {
    report.warn(entry.where + ": effectiveDateTime '" + text + "' has no UTC offset; taken as UTC");
  }
  entry.time = parsed->us;
  return true;
}

void readReferences(const json& wrapper, const json& resource, ObservationEntry& entry) {
  if (wrapper.contains("fullUrl") && wrapper["fullUrl"].is_string()) {
    entry.references.push_back(wrapper["fullUrl"].get<std::string>());
  }
  if (resource.contains("id") && resource["id"].is_string()) {
    entry.references.push_back("Observation/" + resource["id"].get<std::string>());
  }
  const json encounter = resource.value("encounter", json());
  if (encounter.is_object() && encounter.contains("reference") &&
      encounter["reference"].is_string()) {
    entry.encounter = encounter["reference"].get<std::string>();
  }
}

/// Our grouping Observation: members, its all-normal statement, our partial modifier.
bool readPanel(const json& resource, ObservationEntry& entry, ImportReport& report) {
  entry.is_panel = true;
  for (const auto& member : resource.value("hasMember", json::array())) {
    if (!member.is_object() || !member.contains("reference") || !member["reference"].is_string()) {
      report.malformed(entry.where + ": hasMember without a reference");
      return false;
    }
    entry.members.push_back(member["reference"].get<std::string>());
  }
  if (resource.contains("valueCodeableConcept")) {
    const auto codes = codesOf(resource["valueCodeableConcept"], fhir::kValueSystem);
    if (codes.size() != 1 ||
        (codes[0] != fhir::kNoAbnormalFindings && codes[0] != fhir::kAbnormalFindings)) {
      report.malformed(entry.where + ": examination value must be one of " +
                       fhir::kNoAbnormalFindings + ", " + fhir::kAbnormalFindings);
      return false;
    }
    entry.states_all_normal = codes[0] == fhir::kNoAbnormalFindings;
  }
  for (const auto& extension : resource.value("modifierExtension", json::array())) {
    if (extension.is_object() &&
        fhir_codes::textOr(extension, "url", "") == fhir::kPartialExtension) {
      const json reason = extension.value("valueString", json());
      entry.partial_reason = reason.is_string() && !reason.get<std::string>().empty()
                                 ? reason.get<std::string>()
                                 : "marked partial by the sender";
    }
  }
  return true;
}

/// Our anatomy code and an FMA coding must name the same catalogued structure.
bool readBodySite(const json& body_site, const AnatomyCatalog& anatomy, ObservationEntry& entry,
                  ImportReport& report) {
  const auto ours = codesOf(body_site, fhir::kAnatomySystem);
  const auto fma = codesOf(body_site, fhir::kFmaSystem);
  std::set<std::string> named;
  bool unknown = false;
  for (const auto& code : ours) {
    const Structure* structure = anatomy.structure(code);
    unknown |= !structure;
    if (structure) named.insert(structure->id);
  }
  for (const auto& code : fma) {
    const Structure* structure = anatomy.structureByFmaId("FMA:" + code);
    // An FMA id we do not catalogue next to our own code cannot be checked: keep ours.
    if (structure) named.insert(structure->id);
    unknown |= !structure && ours.empty();
  }
  if (named.size() > 1) {
    report.malformed(entry.where + ": bodySite codes name different structures (" +
                     describeCodings(body_site) + ")");
    return false;
  }
  if (named.empty() || unknown) {
    if (!report.unknown(entry.where + ": unknown body site " + describeCodings(body_site))) {
      return false;
    }
    entry.skipped = "unknown body site";
    return true;
  }
  entry.structure = *named.begin();
  return true;
}

/// Laterality extensions and SNOMED CT left/right codings in bodySite must agree; none =
/// midline.
bool readLaterality(const json& body_site, ObservationEntry& entry, ImportReport& report) {
  if (!entry.skipped.empty()) return true;
  std::vector<std::string> codes = codesOf(body_site, fhir::kSnomed);
  std::size_t extensions = 0;
  if (body_site.is_object() && body_site.contains("extension") &&
      body_site["extension"].is_array()) {
    for (const auto& extension : body_site["extension"]) {
      if (!extension.is_object() ||
          fhir_codes::textOr(extension, "url", "") != fhir::kLateralityExtension) {
        continue;
      }
      ++extensions;
      const auto found = codesOf(extension.value("valueCodeableConcept", json()), fhir::kSnomed);
      codes.insert(codes.end(), found.begin(), found.end());
      if (found.empty()) codes.push_back("(no SNOMED CT code)");
    }
  }
  const std::set<std::string> distinct(codes.begin(), codes.end());
  if (distinct.size() > 1) {
    report.malformed(entry.where + ": contradictory lateralities (" + std::to_string(extensions) +
                     " laterality extension(s), codes differ)");
    return false;
  }
  if (distinct.empty()) {
    entry.side = Side::kNone;
  } else if (*distinct.begin() == fhir::kSnomedLeft) {
    entry.side = Side::kLeft;
  } else if (*distinct.begin() == fhir::kSnomedRight) {
    entry.side = Side::kRight;
  } else {
    if (!report.unknown(entry.where + ": laterality is neither SNOMED CT " + fhir::kSnomedLeft +
                        " (left) nor " + fhir::kSnomedRight + " (right)")) {
      return false;
    }
    entry.skipped = "unknown laterality";
  }
  return true;
}

std::optional<Value> integerScore(const json& number, const std::string& where,
                                  ImportReport& report) {
  const double value = number.get<double>();
  if (!number.is_number_integer() && std::floor(value) != value) {
    report.malformed(where + ": the value is not an integer score");
    return std::nullopt;
  }
  if (std::fabs(value) > 1e6) {
    report.malformed(where + ": the value is out of range");
    return std::nullopt;
  }
  return Value::number(static_cast<int>(value));
}

/// valueQuantity: a plain integer score: no comparator, no unit other than a score.
std::optional<Value> quantityScore(const json& quantity, const std::string& where,
                                   ImportReport& report) {
  if (!quantity.is_object() || !quantity.contains("value") || !quantity["value"].is_number()) {
    report.malformed(where + ": valueQuantity has no numeric value");
    return std::nullopt;
  }
  if (quantity.contains("comparator")) {
    report.malformed(where + ": valueQuantity has a comparator; a score must be exact");
    return std::nullopt;
  }
  const std::string unit = fhir_codes::textOr(quantity, "unit", "");
  const std::string unit_code = fhir_codes::textOr(quantity, "code", "");
  const std::string system = fhir_codes::textOr(quantity, "system", "");
  const auto isScore = [](const std::string& u) {
    return u.empty() || u == "{score}" || u == "{Score}" || u == "score" || u == "1";
  };
  if (!isScore(unit) || !isScore(unit_code) || (!system.empty() && system != kUcum)) {
    report.malformed(where + ": valueQuantity unit '" + (unit.empty() ? unit_code : unit) +
                     "' is not a score");
    return std::nullopt;
  }
  return integerScore(quantity["value"], where, report);
}

/// Exactly one value[x] of a supported type; dataAbsentReason makes the observation skipped
/// (its examination partial), never a normal value.
bool readValue(const json& resource, ObservationEntry& entry, ImportReport& report) {
  std::vector<std::string> keys;
  for (const auto& [key, unused] : resource.items()) {
    if (key.rfind("value", 0) == 0) keys.push_back(key);
  }
  if (keys.size() > 1) {
    report.malformed(entry.where + ": " + std::to_string(keys.size()) + " values (" + keys[0] +
                     ", " + keys[1] + "); an Observation has one value[x]");
    return false;
  }
  if (keys.empty()) {
    if (resource.contains("dataAbsentReason")) {
      report.warn(entry.where + ": no value (dataAbsentReason); the examination is partial");
      entry.skipped = "no value recorded";
      return true;
    }
    report.malformed(entry.where +
                     ": no valueInteger, valueBoolean, valueQuantity or valueCodeableConcept");
    return false;
  }
  if (!entry.skipped.empty()) return true;
  const std::string& key = keys[0];
  const json& element = resource[key];
  std::optional<Value> value;
  if (key == "valueInteger" && element.is_number_integer()) {
    value = integerScore(element, entry.where, report);
  } else if (key == "valueBoolean" && element.is_boolean()) {
    value = Value::label(element.get<bool>() ? "true" : "false");
  } else if (key == "valueQuantity") {
    value = quantityScore(element, entry.where, report);
  } else if (key == "valueCodeableConcept") {
    const auto codes = codesOf(element, fhir::kValueSystem);
    if (codes.size() > 1) {
      report.malformed(entry.where +
                       ": valueCodeableConcept has several codes of our value system");
      return false;
    }
    if (codes.empty()) {
      if (!report.unknown(entry.where + ": valueCodeableConcept has no code of our value system " +
                          fhir::kValueSystem)) {
        return false;
      }
      entry.skipped = "unknown value code";
      return true;
    }
    value = Value::label(codes[0]);
  } else {
    report.malformed(entry.where + ": " + key +
                     " is not a supported value (or has the wrong type)");
    return false;
  }
  if (!value) return false;
  // The domain check is the validator's: it names the property and the finding.
  entry.value = *value;
  return true;
}

}  // namespace

std::optional<ObservationEntry> readObservationEntry(const json& wrapper, std::size_t index,
                                                     const EncodingModel& model,
                                                     const FhirImportOptions& options,
                                                     ImportReport& report) {
  const json resource = wrapper.is_object() ? wrapper.value("resource", json()) : json();
  ObservationEntry entry;
  entry.index = index;
  const json id = resource.is_object() ? resource.value("id", json()) : json();
  entry.where = "entry " + std::to_string(index) + " (Observation " +
                (id.is_string() ? id.get<std::string>() : std::string("?")) + ")";
  if (!readStatus(resource, entry, report)) return std::nullopt;
  std::vector<std::string> modifiers;
  collectModifiers(resource, modifiers);
  const json code = resource.value("code", json());
  const auto our_codes = codesOf(code, fhir::kCodeSystem);
  const bool panel = our_codes.size() == 1 && our_codes[0] == fhir::kExaminationCode;
  for (const auto& url : modifiers) {
    if (!(panel && url == fhir::kPartialExtension)) {
      report.malformed(entry.where + ": modifierExtension '" + url +
                       "' is not understood; FHIR forbids processing such a resource");
      return std::nullopt;
    }
  }
  if (!readSubject(resource, entry, report) ||
      !readTime(resource, entry, options.plausibility, report)) {
    return std::nullopt;
  }
  readReferences(wrapper, resource, entry);
  if (panel) return readPanel(resource, entry, report) ? std::optional(entry) : std::nullopt;
  if (our_codes.size() > 1) {
    report.malformed(entry.where + ": code has " + std::to_string(our_codes.size()) +
                     " codings of our code system");
    return std::nullopt;
  }
  const auto coded =
      our_codes.empty() ? std::nullopt : fhir_codes::propertyOfCode(model, our_codes[0]);
  if (!coded) {
    if (!report.unknown(entry.where + ": unknown code " + describeCodings(code))) {
      return std::nullopt;
    }
    entry.skipped = "unknown code";
    return entry;
  }
  entry.category = coded->category->id;
  entry.prop_type = coded->prop_type;
  const json body_site = resource.value("bodySite", json());
  if (!readBodySite(body_site, model.anatomy(), entry, report) ||
      !readLaterality(body_site, entry, report) || !readValue(resource, entry, report)) {
    return std::nullopt;
  }
  return entry;
}

}  // namespace vicc_anatomy_viz::fhir_import
