#include "vicc_anatomy_viz/patient_record.hpp"

#include <cctype>

#include "vicc_anatomy_viz/time_format.hpp"

namespace vicc_anatomy_viz {

bool Finding::operator==(const Finding& other) const {
  return category == other.category && structure == other.structure && side == other.side &&
         values == other.values;
}

std::string Finding::describe() const {
  std::string text = category + " on " + structure;
  if (side != Side::kNone) text += " " + toString(side);
  return text;
}

std::string Examination::describe() const {
  return "patient " + patient_id + ", examination " + formatTimestamp(taken_at_us);
}

std::string toString(ExaminationStatus status) {
  return status == ExaminationStatus::kPreliminary ? "preliminary" : "final";
}

std::optional<ExaminationStatus> examinationStatusFromString(const std::string& text) {
  if (text == "final") return ExaminationStatus::kFinal;
  if (text == "preliminary") return ExaminationStatus::kPreliminary;
  return std::nullopt;
}

std::string patientIdProblem(const std::string& patient_id) {
  if (patient_id.empty()) return "patient id is empty";
  if (patient_id.size() > 64) return "patient id is longer than 64 characters";
  if (!std::isalnum(static_cast<unsigned char>(patient_id.front()))) {
    return "patient id must start with a letter or digit";
  }
  for (const char c : patient_id) {
    const bool ok = std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.';
    if (!ok) {
      return "patient id may only contain letters, digits, '-', '_' and '.' (pseudonyms, not "
             "names)";
    }
  }
  return "";
}

}  // namespace vicc_anatomy_viz
