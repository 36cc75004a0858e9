#pragma once
// The patient panel's patient selector: the patients the status server lists and the one
// selected. A selection is never moved to another patient behind the user's back: when the
// selected patient is missing from a new list it stays selected and is reported as not listed.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace vicc_anatomy_viz::panel {

struct PatientItem {
  std::string id;
  std::uint32_t examination_count = 0;
  std::string first_examination;  ///< ISO 8601
  std::string last_examination;
};

class PatientListState {
 public:
  void setPatients(std::vector<PatientItem> patients);
  const std::vector<PatientItem>& patients() const { return patients_; }
  bool listed() const { return listed_; }  ///< a list has been received

  void select(const std::string& id) { selected_ = id; }
  const std::string& selected() const { return selected_; }
  std::optional<std::size_t> selectedIndex() const;
  /// False when a patient is selected that the last list did not contain.
  bool selectedIsListed() const { return selected_.empty() || selectedIndex().has_value(); }

 private:
  std::vector<PatientItem> patients_;
  bool listed_ = false;
  std::string selected_;
};

/// "SDH-046 (2 examinations, 2023-03-06 to 2023-03-10)": dates shown as the calendar day.
std::string describePatient(const PatientItem& patient);

}  // namespace vicc_anatomy_viz::panel
