#pragma once
// HL7 FHIR R4 exchange: a Bundle of Observation resources. Each examination is one grouping
// Observation (code "examination", an identifier of its own, hasMember -> its findings, and a
// value that states "no abnormal findings" or "abnormal findings", so an all-normal
// examination survives the exchange); each recorded property value is one member Observation:
// code (our code system: "<category>.<property>"), subject (pseudonym identifier),
// effectiveDateTime, bodySite (structure code, FMA coding, laterality extension with SNOMED CT
// left/right) and valueInteger / valueCodeableConcept / valueBoolean. A partial examination
// carries our modifierExtension (a receiver that does not understand it must not read the
// missing findings as normal).

#include <set>
#include <string>
#include <utility>
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
constexpr const char* kExaminationIdentifierSystem =
    "https://vicc.example.org/fhir/NamingSystem/examination";
constexpr const char* kExaminationCode = "examination";
constexpr const char* kNoAbnormalFindings = "no-abnormal-findings";
constexpr const char* kAbnormalFindings = "abnormal-findings";
constexpr const char* kPartialExtension =
    "https://vicc.example.org/fhir/StructureDefinition/examination-partial";
constexpr const char* kSnomed = "http://snomed.info/sct";
constexpr const char* kSnomedLeft = "7771000";
constexpr const char* kSnomedRight = "24028007";
}  // namespace fhir

struct FhirImportOptions {
  /// Unknown codes / body sites are always reported; with this set the remaining
  /// observations are imported and their examination is stored as partial, otherwise the
  /// whole bundle is rejected.
  bool skip_unknown = false;
  /// Observations that name no examination (no grouping Observation, no encounter) belong
  /// to one examination of their patient while they lie within this many seconds of its
  /// first observation (foreign feeds stamp one examination's values seconds apart).
  int grouping_window_seconds = 600;
  TimePlausibility plausibility;  ///< examination times outside it are rejected
  void validate() const;          ///< throws std::invalid_argument
};

struct FhirImport {
  std::vector<Examination> examinations;
  std::vector<std::string> warnings;  ///< skipped entries, with the reason and entry index
};

/// `amended`: (patient, time) of examinations that superseded an earlier version; they are
/// exported with status "amended" (when final).
nlohmann::json examinationsToFhirBundle(
    const std::vector<Examination>& examinations, const EncodingModel& model,
    const std::set<std::pair<std::string, TimestampUs>>& amended = {});

/// Throws ExchangeError when the document is not a Bundle, ValidationError listing every
/// malformed or (without skip_unknown) unknown observation by entry index and id.
FhirImport examinationsFromFhirBundle(const nlohmann::json& bundle, const EncodingModel& model,
                                      const FhirImportOptions& options = {});

bool isFhirBundle(const nlohmann::json& document);

}  // namespace vicc_anatomy_viz
