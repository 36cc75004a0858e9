#include "vicc_anatomy_viz/panel_logic/patient_list_state.hpp"

namespace vicc_anatomy_viz::panel {

void PatientListState::setPatients(std::vector<PatientItem> patients) {
  patients_ = std::move(patients);
  listed_ = true;
}

std::optional<std::size_t> PatientListState::selectedIndex() const {
  for (std::size_t i = 0; i < patients_.size(); ++i) {
    if (patients_[i].id == selected_) return i;
  }
  return std::nullopt;
}

std::string describePatient(const PatientItem& patient) {
  const auto day = [](const std::string& time) { return time.substr(0, 10); };
  std::string text = patient.id + " (" + std::to_string(patient.examination_count) +
                     (patient.examination_count == 1 ? " examination" : " examinations");
  if (patient.examination_count > 0) {
    text += ", " + day(patient.first_examination);
    if (patient.examination_count > 1) text += " to " + day(patient.last_examination);
  }
  return text + ")";
}

}  // namespace vicc_anatomy_viz::panel
