#include "vicc_anatomy_viz/avatar_view/alternation.hpp"

#include <algorithm>
#include <cmath>

namespace vicc_anatomy_viz::avatar_view {

AlternationCycle::AlternationCycle(const AvatarDrawState& state, double period_s)
    : period_s_(std::isfinite(period_s) && period_s > 0.0 ? period_s : 0.0) {
  std::map<int, std::vector<std::size_t>> all;
  for (std::size_t i = 0; i < state.items.size(); ++i) {
    group_of_item_.push_back(state.items[i].alternation_group);
    if (state.items[i].alternation_group >= 0) all[state.items[i].alternation_group].push_back(i);
  }
  // Members in the alternation's view order; a group left with one drawn member (the others
  // hidden or invalid) does not alternate.
  for (auto& [group, items] : all) {
    std::stable_sort(items.begin(), items.end(), [&state](std::size_t a, std::size_t b) {
      return state.items[a].alternation_rank < state.items[b].alternation_rank;
    });
    if (items.size() > 1) members_.emplace(group, std::move(items));
  }
}

long AlternationCycle::step(double time_s) const {
  if (period_s_ <= 0.0 || !std::isfinite(time_s)) return 0;
  return static_cast<long>(std::floor(time_s / period_s_));
}

bool AlternationCycle::shown(std::size_t item, double time_s) const {
  if (item >= group_of_item_.size()) return false;
  const auto group = members_.find(group_of_item_[item]);
  if (group == members_.end()) return true;
  const std::vector<std::size_t>& items = group->second;
  const long count = static_cast<long>(items.size());
  const long active = ((step(time_s) % count) + count) % count;
  return items[static_cast<std::size_t>(active)] == item;
}

}  // namespace vicc_anatomy_viz::avatar_view
