#pragma once
// Patient records: pseudonymous patients, timestamped examinations, findings that reference
// category, structure and side with their recorded property values.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "vicc_anatomy_viz/anatomy_catalog.hpp"
#include "vicc_anatomy_viz/data_model.hpp"
#include "vicc_anatomy_viz/time_format.hpp"

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

/// The FHIR-like status of an examination: a preliminary one is kept and shown as such.
enum class ExaminationStatus { kFinal, kPreliminary };
std::string toString(ExaminationStatus status);
std::optional<ExaminationStatus> examinationStatusFromString(const std::string& text);

/// One examination is a status snapshot: structures without a finding are normal -- unless
/// the examination is partial (some recorded content could not be imported), in which case
/// a missing finding means "unknown", and every display must say so.
struct Examination {
  std::string patient_id;
  TimestampUs taken_at_us = 0;  ///< microseconds since the Unix epoch, UTC
  std::string view_id;
  std::string source;  ///< provenance: json, fhir, cli, service
  ExaminationStatus status = ExaminationStatus::kFinal;
  bool partial = false;
  std::string partial_reason;    ///< what is missing (no values: "2 observations not imported")
  std::int64_t recorded_at = 0;  ///< when the store wrote it (UTC seconds; 0: not stored yet)
  std::vector<Finding> findings;

  /// "patient P-1, examination 2023-03-06T08:30:00Z"
  std::string describe() const;
};

/// An earlier version of an examination that a replacement superseded (kept as history).
struct SupersededExamination {
  Examination examination;         ///< as it was, with its own source and recorded_at
  std::int64_t superseded_at = 0;  ///< UTC seconds
  std::string replaced_by_source;  ///< provenance of the replacement
};

struct PatientSummary {
  std::string patient_id;
  std::size_t examination_count = 0;
  TimestampUs first_examination = 0;
  TimestampUs last_examination = 0;
};

/// Pseudonymous ids only: 1-64 characters of [A-Za-z0-9._-], starting alphanumeric. Returns
/// "" when valid, else the reason (the id itself is not repeated: it might be a name).
std::string patientIdProblem(const std::string& patient_id);

}  // namespace vicc_anatomy_viz
