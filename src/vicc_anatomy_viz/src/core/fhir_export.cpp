// FHIR R4 export: one Observation per recorded property value.
#include <cstdio>

#include "fhir_codes.hpp"
#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/fhir_bundle.hpp"
#include "vicc_anatomy_viz/fhir_standard_codes.hpp"
#include "vicc_anatomy_viz/time_format.hpp"

namespace vicc_anatomy_viz {

using fhir_codes::coding;
using nlohmann::json;

namespace {

std::uint64_t fnv1a(const std::string& key, std::uint64_t hash = 1469598103934665603ULL) {
  for (const unsigned char c : key) {
    hash ^= c;
    hash *= 1099511628211ULL;
  }
  return hash;
}

/// Stable resource ids, so that exporting twice gives the same Bundle.
std::string resourceId(const std::string& key) {
  char buffer[24];
  std::snprintf(buffer, sizeof(buffer), "vicc-%016llx",
                static_cast<unsigned long long>(fnv1a(key)));
  return buffer;
}

/// A stable urn:uuid (version-4 layout) for the Bundle's fullUrl and references.
std::string resourceUrn(const std::string& key) {
  const std::uint64_t high = fnv1a(key);
  const std::uint64_t low = fnv1a(key, high ^ 0x9e3779b97f4a7c15ULL);
  char buffer[48];
  std::snprintf(buffer, sizeof(buffer), "urn:uuid:%08llx-%04llx-4%03llx-%04llx-%012llx",
                static_cast<unsigned long long>(high >> 32),
                static_cast<unsigned long long>((high >> 16) & 0xffff),
                static_cast<unsigned long long>(high & 0xfff),
                static_cast<unsigned long long>(0x8000 | (low >> 48 & 0x3fff)),
                static_cast<unsigned long long>(low & 0xffffffffffffULL));
  return buffer;
}

json valueElement(const Domain& domain, const Value& value) {
  if (value.isNumber()) return {{"valueInteger", value.asNumber()}};
  if (domain.isBinary()) return {{"valueBoolean", value.asLabel() == "true"}};
  return {{"valueCodeableConcept",
           {{"coding", json::array({coding(fhir::kValueSystem, value.asLabel(), "")})}}}};
}

/// Our structure code, its FMA coding where catalogued, and the side as the laterality
/// extension (SNOMED CT qualifier values).
json bodySite(const AnatomyCatalog& anatomy, const Structure& structure, Side side) {
  json site = {
      {"coding", json::array({coding(fhir::kAnatomySystem, structure.id, structure.name)})},
      {"text", anatomy.displayName(structure, side)}};
  if (!structure.fma_id.empty()) {
    site["coding"].push_back(coding(fhir::kFmaSystem, structure.fma_id.substr(4), structure.name));
  }
  if (side != Side::kNone) {
    const bool left = side == Side::kLeft;
    const json laterality = coding(fhir::kSnomed, left ? fhir::kSnomedLeft : fhir::kSnomedRight,
                                   left ? "Left" : "Right");
    site["extension"] =
        json::array({{{"url", fhir::kLateralityExtension},
                      {"valueCodeableConcept", {{"coding", json::array({laterality})}}}}});
  }
  return site;
}

/// Status, category, subject and time shared by an examination's Observations.
json commonElements(const Examination& examination, bool amended) {
  const json exam_category = json::array(
      {{{"coding", json::array({coding("http://terminology.hl7.org/CodeSystem/observation-category",
                                       "exam", "Exam")})}}});
  const std::string status = examination.status == ExaminationStatus::kPreliminary
                                 ? "preliminary"
                                 : (amended ? "amended" : "final");
  return {
      {"status", status},
      {"category", exam_category},
      {"subject",
       {{"identifier", {{"system", fhir::kPseudonymSystem}, {"value", examination.patient_id}}}}},
      {"effectiveDateTime", formatTimestamp(examination.taken_at_us)}};
}

/// The member Observations of one examination, one per recorded property value.
std::vector<json> findingObservations(const Examination& examination, const EncodingModel& model,
                                      const json& common) {
  std::vector<json> out;
  const AnatomyCatalog& anatomy = model.anatomy();
  const std::string when = formatTimestamp(examination.taken_at_us);
  for (const auto& finding : examination.findings) {
    const Structure* structure = anatomy.structure(finding.structure);
    for (const auto& [prop_type, value] : finding.values) {
      const std::string code = finding.category + "." + prop_type;
      const auto coded = fhir_codes::propertyOfCode(model, code);
      if (!coded || !structure) {
        // Stored data is validated; exporting less than the record would understate it.
        throw ExchangeError(examination.describe() + ": finding " + finding.describe() +
                            " does not fit the configuration; nothing was exported");
      }
      const std::string key = examination.patient_id + "|" + when + "|" + code + "|" +
                              finding.structure + "|" + toString(finding.side);
      json observation = {{"resourceType", "Observation"}, {"id", resourceId(key)}};
      observation.update(common);
      // Ours first (the import reads it), then the standard codes of the same property.
      json codings = json::array(
          {coding(fhir::kCodeSystem, code, coded->category->label + " " + coded->label)});
      for (const auto& standard : standardCodings(code)) codings.push_back(standard);
      observation["code"] = {{"coding", codings}};
      observation["bodySite"] = bodySite(anatomy, *structure, finding.side);
      observation.update(valueElement(*coded->domain, value));
      out.push_back({{"fullUrl", resourceUrn(key)}, {"resource", observation}});
    }
  }
  return out;
}

/// The grouping Observation: identity, "no abnormal findings" or "abnormal findings",
/// hasMember, and the partial modifier.
json examinationObservation(const Examination& examination, const json& common,
                            const std::vector<json>& members) {
  const std::string identity =
      examination.patient_id + "/" + formatTimestamp(examination.taken_at_us);
  json panel = {
      {"resourceType", "Observation"},
      {"id", resourceId(identity + "|examination")},
      {"identifier",
       json::array({{{"system", fhir::kExaminationIdentifierSystem}, {"value", identity}}})}};
  panel.update(common);
  panel["code"] = {{"coding", json::array({coding(fhir::kCodeSystem, fhir::kExaminationCode,
                                                  "Neurological examination")})}};
  const bool normal = members.empty();
  panel["valueCodeableConcept"] = {
      {"coding", json::array({coding(fhir::kValueSystem,
                                     normal ? fhir::kNoAbnormalFindings : fhir::kAbnormalFindings,
                                     normal ? "No abnormal findings" : "Abnormal findings")})}};
  if (!members.empty()) {
    json references = json::array();
    for (const auto& member : members) references.push_back({{"reference", member["fullUrl"]}});
    panel["hasMember"] = references;
  }
  if (examination.partial) {
    panel["modifierExtension"] = json::array(
        {{{"url", fhir::kPartialExtension}, {"valueString", examination.partial_reason}}});
  }
  if (examination.recorded_at != 0) {
    panel["meta"] = {{"lastUpdated", formatTimestamp(examination.recorded_at * kMicrosPerSecond)},
                     {"source", "urn:vicc:record-source:" + examination.source}};
  }
  return {{"fullUrl", resourceUrn(identity + "|examination")}, {"resource", panel}};
}

}  // namespace

json examinationsToFhirBundle(const std::vector<Examination>& examinations,
                              const EncodingModel& model,
                              const std::set<std::pair<std::string, TimestampUs>>& amended) {
  json entries = json::array();
  for (const auto& examination : examinations) {
    const bool was_amended = amended.count({examination.patient_id, examination.taken_at_us}) > 0;
    const json common = commonElements(examination, was_amended);
    const std::vector<json> members = findingObservations(examination, model, common);
    entries.push_back(examinationObservation(examination, common, members));
    for (const auto& member : members) entries.push_back(member);
  }
  json bundle = {{"resourceType", "Bundle"}, {"type", "collection"}};
  // FHIR forbids empty arrays: an empty export has no entry element at all.
  if (!entries.empty()) bundle["entry"] = entries;
  return bundle;
}

}  // namespace vicc_anatomy_viz
