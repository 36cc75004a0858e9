// FHIR R4 export: one Observation per recorded property value.
#include <cstdio>

#include "fhir_codes.hpp"
#include "vicc_anatomy_viz/fhir_bundle.hpp"
#include "vicc_anatomy_viz/time_format.hpp"

namespace vicc_anatomy_viz {

using fhir_codes::coding;
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

}  // namespace

bool isFhirBundle(const json& document) {
  return fhir_codes::textOr(document, "resourceType", "") == "Bundle";
}

json examinationsToFhirBundle(const std::vector<Examination>& examinations,
                              const EncodingModel& model) {
  json entries = json::array();
  const AnatomyCatalog& anatomy = model.anatomy();
  const json exam_category = json::array(
      {{{"coding", json::array({coding("http://terminology.hl7.org/CodeSystem/observation-category",
                                       "exam", "Exam")})}}});
  for (const auto& examination : examinations) {
    const std::string when = formatTimestamp(examination.taken_at);
    for (const auto& finding : examination.findings) {
      const Structure* structure = anatomy.structure(finding.structure);
      for (const auto& [prop_type, value] : finding.values) {
        const std::string code = finding.category + "." + prop_type;
        const auto coded = fhir_codes::propertyOfCode(model, code);
        if (!coded || !structure) continue;  // stored data is validated; cannot happen
        json observation = {
            {"resourceType", "Observation"},
            {"id", resourceId(examination.patient_id + "|" + when + "|" + code + "|" +
                              finding.structure + "|" + toString(finding.side))},
            {"status", "final"},
            {"category", exam_category},
            {"code",
             {{"coding", json::array({coding(fhir::kCodeSystem, code,
                                             coded->category->label + " " + coded->label)})}}},
            {"subject",
             {{"identifier",
               {{"system", fhir::kPseudonymSystem}, {"value", examination.patient_id}}}}},
            {"effectiveDateTime", when},
            {"bodySite", bodySite(anatomy, *structure, finding.side)}};
        observation.update(valueElement(*coded->domain, value));
        entries.push_back({{"resource", observation}});
      }
    }
  }
  return {{"resourceType", "Bundle"}, {"type", "collection"}, {"entry", entries}};
}

}  // namespace vicc_anatomy_viz
