#pragma once
// HL7 FHIR R4 exchange: a Bundle of Observation resources, one per recorded property value:
// code (our code system: "<category>.<property>"), subject (pseudonym identifier),
// effectiveDateTime, bodySite (structure code, FMA coding, laterality extension with SNOMED CT
// left/right) and valueInteger / valueCodeableConcept / valueBoolean.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "vicc_anatomy_viz/encoding_model.hpp"
#include "vicc_anatomy_viz/patient_record.hpp"

namespace vicc_anatomy_viz {

namespace fhir {
constexpr const char* kCodeSystem = "https://vicc.example.org/fhir/CodeSystem/neurological-status";
constexpr const char* kValueSystem =
    "https://vicc.example.org/fhir/CodeSystem/neurological-status-values";
constexpr const char* kAnatomySystem = "https://vicc.example.org/fhir/CodeSystem/anatomy";
// FMA has no FHIR-registered URI; FHIR's rule for UMLS sources gives .../umls/<SAB>.
constexpr const char* kFmaSystem = "http://www.nlm.nih.gov/research/umls/fma";
constexpr const char* kPseudonymSystem = "https://vicc.example.org/fhir/NamingSystem/pseudonym";
constexpr const char* kLateralityExtension =
    "http://hl7.org/fhir/StructureDefinition/observation-structureLaterality";
constexpr const char* kSnomed = "http://snomed.info/sct";
constexpr const char* kSnomedLeft = "7771000";
constexpr const char* kSnomedRight = "24028007";
}  // namespace fhir

struct FhirImportOptions {
  /// Unknown codes / body sites are always reported; with this set the remaining
  /// observations are imported, otherwise the whole bundle is rejected.
  bool skip_unknown = false;
};

struct FhirImport {
  std::vector<Examination> examinations;
  std::vector<std::string> warnings;  ///< skipped entries, with the reason and entry index
};

nlohmann::json examinationsToFhirBundle(const std::vector<Examination>& examinations,
                                        const EncodingModel& model);

/// Throws ExchangeError when the document is not a Bundle, ValidationError listing every
/// malformed or (without skip_unknown) unknown observation by entry index and id.
FhirImport examinationsFromFhirBundle(const nlohmann::json& bundle, const EncodingModel& model,
                                      const FhirImportOptions& options = {});

bool isFhirBundle(const nlohmann::json& document);

}  // namespace vicc_anatomy_viz
