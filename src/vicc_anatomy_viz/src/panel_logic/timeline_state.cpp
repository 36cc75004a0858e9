#include "vicc_anatomy_viz/panel_logic/timeline_state.hpp"

#include <algorithm>
#include <stdexcept>

namespace vicc_anatomy_viz::panel {

std::vector<std::string> TimelineState::setDates(const std::vector<std::string>& dates) {
  std::vector<std::string> problems;
  dates_.clear();
  for (const auto& text : dates) {
    std::string problem;
    const auto parsed = parseTime(text, &problem);
    if (!parsed) {
      problems.push_back("examination date '" + text + "': " + problem);
      continue;
    }
    dates_.push_back({text, parsed->us});
  }
  std::stable_sort(dates_.begin(), dates_.end(),
                   [](const Entry& a, const Entry& b) { return a.time < b.time; });
  return problems;
}

void TimelineState::clearDates() { dates_.clear(); }

void TimelineState::followLatest() { fixed_date_.reset(); }

void TimelineState::requestDate(const std::string& date) {
  if (date.empty()) {
    followLatest();
    return;
  }
  const auto bound = parseUpperBound(date);
  if (!bound) {
    throw std::invalid_argument("date '" + date +
                                "' is not ISO 8601 (YYYY-MM-DD or YYYY-MM-DDTHH:MM[:SS][Z])");
  }
  fixed_date_ = date;
  fixed_bound_ = *bound;
}

bool TimelineState::selectIndex(std::size_t index) {
  if (index >= dates_.size()) return false;
  fixed_date_ = dates_[index].text;
  fixed_bound_ = dates_[index].time;
  return true;
}

std::optional<std::size_t> TimelineState::sliderIndex() const {
  if (dates_.empty()) return std::nullopt;
  if (!fixed_date_) return dates_.size() - 1;
  // The last examination at or before the requested bound.
  const auto after =
      std::upper_bound(dates_.begin(), dates_.end(), fixed_bound_,
                       [](TimestampUs bound, const Entry& entry) { return bound < entry.time; });
  if (after == dates_.begin()) return std::nullopt;
  return static_cast<std::size_t>(after - dates_.begin()) - 1;
}

std::string TimelineState::describe() const {
  if (dates_.empty()) return "no examinations";
  const auto index = sliderIndex();
  if (!index) return "no examination at or before " + *fixed_date_;
  const std::string position =
      " (" + std::to_string(*index + 1) + " of " + std::to_string(dates_.size()) + ")";
  return (fixed_date_ ? "" : "latest: ") + dates_[*index].text + position;
}

}  // namespace vicc_anatomy_viz::panel
