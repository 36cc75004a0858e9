#pragma once
// Our JSON exchange format for patient records:
//   {"format": "vicc-patient-records", "version": 1, "patients": [{"id": "P-1",
//     "examinations": [{"taken_at": "2023-03-06T08:30:00Z", "findings": [{"category": ...,
//     "structure": ..., "side": "left", "values": {"intensity": 8, "trigger": "constant"}}]}]}]}
// and a single examination for `record`:
//   {"format": "vicc-examination", "version": 1, "patient": "P-1", "taken_at": ..., "findings":
//   [...]}

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "vicc_anatomy_viz/patient_record.hpp"

namespace vicc_anatomy_viz {

constexpr const char* kRecordsFormat = "vicc-patient-records";
constexpr const char* kExaminationFormat = "vicc-examination";

/// Reads either format. Throws ExchangeError for unreadable JSON, ValidationError listing
/// every malformed item by its JSON path (wrong types, bad timestamps, bad ids).
std::vector<Examination> examinationsFromJson(const nlohmann::json& document,
                                              const std::string& source = "json");
nlohmann::json recordsToJson(const std::vector<Examination>& examinations);
nlohmann::json examinationToJson(const Examination& examination);

/// Parses JSON text; ExchangeError naming `origin` and the position on a syntax error.
nlohmann::json parseJsonText(const std::string& text, const std::string& origin);
std::string readTextFile(const std::string& path);  ///< ExchangeError if unreadable

}  // namespace vicc_anatomy_viz
