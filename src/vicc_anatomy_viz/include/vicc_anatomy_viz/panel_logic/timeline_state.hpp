#pragma once
// The patient panel's timeline (thesis 4.4.1, "Visualization of Temporal Changes"): the selected
// patient's examination dates on a slider and the date requested from the status server. The
// request is either "latest" (follows a newly recorded examination) or a fixed date, which is kept
// when the list of dates changes; the slider then sits on the examination at or before it, as
// the server resolves a date.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "vicc_anatomy_viz/time_format.hpp"

namespace vicc_anatomy_viz::panel {

class TimelineState {
 public:
  /// Replaces the examination dates (ISO 8601, as ListExaminationDates answers). They are
  /// ordered oldest first; an entry that does not parse is left out and named in the result.
  std::vector<std::string> setDates(const std::vector<std::string>& dates);
  void clearDates();

  /// "latest": the newest examination, also after a new one is recorded.
  void followLatest();
  bool followsLatest() const { return !fixed_date_; }

  /// A fixed date, "" meaning latest. Throws std::invalid_argument naming the text when it is
  /// not an ISO 8601 date or date-time.
  void requestDate(const std::string& date);
  /// Fixes the request to the examination at `index`; false (and no change) when out of range.
  bool selectIndex(std::size_t index);

  /// What the server is asked for: "" for latest, else the fixed date as given.
  std::string requestedDate() const { return fixed_date_.value_or(""); }

  std::size_t size() const { return dates_.size(); }
  const std::string& dateAt(std::size_t index) const { return dates_.at(index).text; }
  /// Slider position: the examination the request resolves to; nullopt when there are no dates
  /// or the fixed date lies before the first examination.
  std::optional<std::size_t> sliderIndex() const;
  /// "2023-03-06T09:15:00Z (1 of 2)", "latest: ... (2 of 2)", "no examination at or before D".
  std::string describe() const;

 private:
  struct Entry {
    std::string text;
    TimestampUs time;
  };
  std::vector<Entry> dates_;
  std::optional<std::string> fixed_date_;
  TimestampUs fixed_bound_ = 0;  ///< upper bound of fixed_date_ ("at or before")
};

}  // namespace vicc_anatomy_viz::panel
