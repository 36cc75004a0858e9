#include "vicc_anatomy_viz/panel_logic/patient_panel_state.hpp"

#include <stdexcept>

namespace vicc_anatomy_viz::panel {

std::string describeShown(const ShownStatus& status) {
  if (status.patient_id.empty()) return "no patient shown";
  std::string text = status.patient_id + ": ";
  if (!status.has_examination) {
    text += "no examination at or before " +
            (status.requested_date.empty() ? std::string("now") : status.requested_date);
  } else {
    text += "examination " + status.examination_time;
    if (status.examination_status == "preliminary") text += ", PRELIMINARY";
    if (status.partial) {
      text += ", PARTIAL (not recorded: " + status.partial_reason +
              "; a structure without a finding is not known to be normal)";
    }
  }
  if (!status.hidden_categories.empty()) {
    text += "; hidden:";
    for (const auto& id : status.hidden_categories) text += " " + id;
  }
  return text;
}

void PatientPanelState::restore(const PanelSettings& settings) {
  server_ = settings.server;
  patients.select(settings.patient_id);
  try {
    timeline.requestDate(settings.date);
  } catch (const std::invalid_argument&) {
    timeline.followLatest();  // settingsFromKeyValues has reported it already
  }
  categories.setHidden(settings.hidden_categories);
  pending_restore_ = !settings.patient_id.empty();
}

PanelSettings PatientPanelState::settings() const {
  PanelSettings settings;
  settings.server = server_;
  settings.patient_id = patients.selected();
  settings.date = timeline.requestedDate();
  settings.hidden_categories = categories.allHidden();
  return settings;
}

SelectionRequest PatientPanelState::request() const {
  return {patients.selected(), timeline.requestedDate(), categories.requestedHidden()};
}

SelectionRequest PatientPanelState::choosePatient(const std::string& id) {
  if (id != patients.selected()) {
    patients.select(id);
    timeline.clearDates();
    dates_patient_.clear();
  }
  timeline.followLatest();
  pending_restore_ = false;
  return request();
}

std::optional<SelectionRequest> PatientPanelState::chooseDateIndex(std::size_t index) {
  if (!timeline.selectIndex(index)) return std::nullopt;
  return request();
}

SelectionRequest PatientPanelState::chooseLatest() {
  timeline.followLatest();
  return request();
}

SelectionRequest PatientPanelState::chooseCategoryVisible(const std::string& id, bool visible) {
  categories.setVisible(id, visible);
  return request();
}

SelectionRequest PatientPanelState::takePendingRestore() {
  pending_restore_ = false;
  return request();
}

void PatientPanelState::requestAnswered(bool success, const std::optional<ShownStatus>& status) {
  if (requests_in_flight_ > 0) --requests_in_flight_;
  if (success && status) shown_ = *status;
  if (requests_in_flight_ == 0 && shown_) adopt(*shown_);
}

void PatientPanelState::statusPublished(const ShownStatus& status) {
  shown_ = status;
  if (requests_in_flight_ == 0 && !pending_restore_) adopt(status);
}

void PatientPanelState::adopt(const ShownStatus& status) {
  if (status.patient_id != patients.selected()) {
    patients.select(status.patient_id);
    timeline.clearDates();
    dates_patient_.clear();
  }
  try {
    timeline.requestDate(status.requested_date);
  } catch (const std::invalid_argument&) {
    timeline.followLatest();  // the server accepted it, so this does not happen
  }
  categories.setLegend(status.legend);
  categories.setHidden(status.hidden_categories);
}

bool PatientPanelState::datesListed(const std::string& patient,
                                    const std::vector<std::string>& dates,
                                    std::vector<std::string>* problems) {
  if (patient != patients.selected()) return false;
  auto date_problems = timeline.setDates(dates);
  if (problems) *problems = std::move(date_problems);
  dates_patient_ = patient;
  return true;
}

bool PatientPanelState::datesOutdated() const {
  const std::string& patient = patients.selected();
  if (patient.empty()) return false;
  if (dates_patient_ != patient) return true;
  if (!shown_ || shown_->patient_id != patient || !shown_->has_examination) return false;
  for (std::size_t i = 0; i < timeline.size(); ++i) {
    if (timeline.dateAt(i) == shown_->examination_time) return false;
  }
  return true;
}

}  // namespace vicc_anatomy_viz::panel
