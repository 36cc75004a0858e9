#pragma once
// Our JSON exchange format for patient records:
//   {"format": "vicc-patient-records", "version": 1, "patients": [{"id": "P-1",
//     "examinations": [{"taken_at": "2023-03-06T08:30:00Z", "findings": [{"category": ...,
//     "structure": ..., "side": "left", "values": {"intensity": 8, "trigger": "constant"}}]}]}]}
// and a single examination for `record`:
//   {"format": "vicc-examination", "version": 1, "patient": "P-1", "taken_at": ..., "findings":
//   [...]}
// An examination may also carry "status": "final"|"preliminary" (default final) and
// "partial": true with "partial_reason"; exports add "provenance" (source, recorded_at) and,
// per patient, the "superseded" versions (history; read back as a warning, not imported).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "vicc_anatomy_viz/patient_record.hpp"

namespace vicc_anatomy_viz {

constexpr const char* kRecordsFormat = "vicc-patient-records";
constexpr const char* kExaminationFormat = "vicc-examination";

struct JsonImportOptions {
  TimePlausibility plausibility;  ///< examination times outside it are rejected
};

/// Reads either format. Throws ExchangeError for unreadable JSON, ValidationError listing
/// every malformed item by its JSON path (wrong types, bad or implausible timestamps, bad
/// ids). `warnings` (optional) receives what was read but deserves attention (a time without
/// a UTC offset, taken as UTC; history that is not imported).
std::vector<Examination> examinationsFromJson(const nlohmann::json& document,
                                              const std::string& source = "json",
                                              std::vector<std::string>* warnings = nullptr,
                                              const JsonImportOptions& options = {});
nlohmann::json recordsToJson(const std::vector<Examination>& examinations,
                             const std::vector<SupersededExamination>& history = {});
nlohmann::json examinationToJson(const Examination& examination);

/// Parses JSON text; ExchangeError naming `origin` and the position on a syntax error, and
/// for an object with a repeated key ({"intensity": 1, "intensity": 9}: which one is meant?).
nlohmann::json parseJsonText(const std::string& text, const std::string& origin);
std::string readTextFile(const std::string& path);  ///< ExchangeError if unreadable

}  // namespace vicc_anatomy_viz
