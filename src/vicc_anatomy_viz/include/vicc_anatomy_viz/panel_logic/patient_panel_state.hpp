#pragma once
// The patient panel without Qt: the patient list, timeline and category filter, the selection
// they request from the status server, and what the avatar shows. The panel shows the truth:
// a status the server published for another client is adopted; a failed request restores the
// controls to the status still shown; while the panel's own requests are in flight, published
// statuses do not overwrite the user's newer choices.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "vicc_anatomy_viz/panel_logic/category_filter_state.hpp"
#include "vicc_anatomy_viz/panel_logic/panel_settings.hpp"
#include "vicc_anatomy_viz/panel_logic/patient_list_state.hpp"
#include "vicc_anatomy_viz/panel_logic/timeline_state.hpp"

namespace vicc_anatomy_viz::panel {

struct SelectionRequest {
  std::string patient_id;
  std::string date;  ///< "" = latest
  std::vector<std::string> hidden_categories;
};

/// The parts of a vicc_msgs/EncodedStatus the panel shows.
struct ShownStatus {
  std::string patient_id;
  std::string requested_date;
  bool has_examination = false;
  std::string examination_time;
  std::string examination_status;  ///< final | preliminary
  bool partial = false;
  std::string partial_reason;
  std::vector<std::string> hidden_categories;
  std::vector<CategoryItem> legend;
};

/// "Shown: SDH-046, examination 2023-03-06T09:15:00Z", with PRELIMINARY / PARTIAL marks.
std::string describeShown(const ShownStatus& status);

class PatientPanelState {
 public:
  /// Restores a saved configuration (read and validated by settingsFromKeyValues).
  void restore(const PanelSettings& settings);
  PanelSettings settings() const;
  const std::string& server() const { return server_; }

  // User actions; each returns the selection to request.
  SelectionRequest choosePatient(const std::string& id);  ///< timeline back to latest
  std::optional<SelectionRequest> chooseDateIndex(std::size_t index);
  SelectionRequest chooseLatest();
  SelectionRequest chooseCategoryVisible(const std::string& id, bool visible);
  SelectionRequest request() const;

  /// A restored patient the panel still has to request once the server answers.
  bool hasPendingRestore() const { return pending_restore_; }
  SelectionRequest takePendingRestore();

  // The request life cycle and the server's statuses.
  void requestSent() { ++requests_in_flight_; }
  /// The service answered: on success `status` is what is now published; on failure the
  /// controls return to the status still shown.
  void requestAnswered(bool success, const std::optional<ShownStatus>& status);
  /// A status on the latched topic; adopted unless own requests are in flight.
  void statusPublished(const ShownStatus& status);
  std::size_t requestsInFlight() const { return requests_in_flight_; }

  /// The dates ListExaminationDates answered for `patient`; ignored (false) when another patient
  /// is selected by now. `problems` gets the dates that did not parse.
  bool datesListed(const std::string& patient, const std::vector<std::string>& dates,
                   std::vector<std::string>* problems = nullptr);

  const std::optional<ShownStatus>& shown() const { return shown_; }
  /// True when the shown patient's dates have to be (re)fetched: another patient, or an
  /// examination time the timeline does not list.
  bool datesOutdated() const;

  PatientListState patients;
  TimelineState timeline;
  CategoryFilterState categories;

 private:
  void adopt(const ShownStatus& status);

  std::string server_ = kDefaultServer;
  bool pending_restore_ = false;
  std::size_t requests_in_flight_ = 0;
  std::optional<ShownStatus> shown_;
  std::string dates_patient_;  ///< whose dates the timeline holds
};

}  // namespace vicc_anatomy_viz::panel
