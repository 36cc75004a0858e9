#pragma once
// Reads one FHIR Observation of an import: the examination it belongs to (patient, time,
// grouping Observation, encounter) and what it records. Contradictions (two lateralities, two
// body-site codes, two values, a comparator, an unknown modifier) are malformed input, never
// resolved by picking one.

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "vicc_anatomy_viz/encoding_model.hpp"
#include "vicc_anatomy_viz/fhir_bundle.hpp"
#include "vicc_anatomy_viz/patient_record.hpp"

namespace vicc_anatomy_viz::fhir_import {

/// Collects what cannot be imported: malformed observations always reject the bundle; unknown
/// codes do too unless the caller chose to skip them (then they become warnings and make
/// their examination partial).
class ImportReport {
 public:
  ImportReport(bool skip_unknown, std::vector<std::string>& warnings)
      : skip_unknown_(skip_unknown), warnings_(warnings) {}
  void malformed(const std::string& message) { problems_.push_back(message); }
  /// true when the observation is skipped (and its examination becomes partial).
  bool unknown(const std::string& message);
  void warn(const std::string& message) { warnings_.push_back(message); }
  const std::vector<std::string>& problems() const { return problems_; }

 private:
  bool skip_unknown_;
  std::vector<std::string>& warnings_;
  std::vector<std::string> problems_;
};

/// What one Observation entry says.
struct ObservationEntry {
  std::size_t index = 0;
  std::string where;                    ///< "entry 3 (Observation abc)"
  std::vector<std::string> references;  ///< how others refer to it: fullUrl, Observation/id
  std::string patient;
  TimestampUs time = 0;
  ExaminationStatus status = ExaminationStatus::kFinal;
  std::string encounter;  ///< encounter.reference, "" if none

  bool is_panel = false;                  ///< our grouping Observation of an examination
  std::vector<std::string> members;       ///< panel: hasMember references
  std::optional<bool> states_all_normal;  ///< panel: its value, if given
  std::string partial_reason;             ///< panel: our partial modifier's text

  /// A member that is not imported (unknown code with skip_unknown, dataAbsentReason): its
  /// examination is partial. Holds the reason without any value.
  std::string skipped;
  std::string category, structure, prop_type;
  Side side = Side::kNone;
  Value value;
};

/// Reads entry `index`; nullopt when it is malformed, not imported at all (entered in error)
/// or unknown without skip_unknown (all reported).
std::optional<ObservationEntry> readObservationEntry(const nlohmann::json& entry, std::size_t index,
                                                     const EncodingModel& model,
                                                     const FhirImportOptions& options,
                                                     ImportReport& report);

}  // namespace vicc_anatomy_viz::fhir_import
