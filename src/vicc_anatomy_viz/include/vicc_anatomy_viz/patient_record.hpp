#pragma once
// Patient records: pseudonymous patients, timestamped examinations, findings that reference
// category, structure and side with their recorded property values.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "vicc_anatomy_viz/anatomy_catalog.hpp"
#include "vicc_anatomy_viz/data_model.hpp"

namespace vicc_anatomy_viz {

struct Finding {
  std::string category;
  std::string structure;
  Side side = Side::kNone;
  /// Recorded values by property type (or by a property's source type, e.g.
  /// muscle_strength). Omitted properties have their normal value.
  std::map<std::string, Value> values;

  bool operator==(const Finding& other) const;
  /// "radicular_pain on dermatome_L5 left"
  std::string describe() const;
};

/// One examination is a complete status snapshot: structures without a finding are normal.
struct Examination {
  std::string patient_id;
  std::int64_t taken_at = 0;  ///< seconds since the Unix epoch, UTC
  std::string view_id;
  std::string source;  ///< provenance: json, fhir, cli, service
  std::vector<Finding> findings;

  /// "patient P-1, examination 2023-03-06T08:30:00Z"
  std::string describe() const;
};

struct PatientSummary {
  std::string patient_id;
  std::size_t examination_count = 0;
  std::int64_t first_examination = 0;
  std::int64_t last_examination = 0;
};

/// Pseudonymous ids only: 1-64 characters of [A-Za-z0-9._-], starting alphanumeric. Returns
/// "" when valid, else the reason (the id itself is not repeated: it might be a name).
std::string patientIdProblem(const std::string& patient_id);

}  // namespace vicc_anatomy_viz
