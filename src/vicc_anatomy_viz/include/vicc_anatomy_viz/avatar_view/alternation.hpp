#pragma once
// Alternating display of categories that share one structure (thesis 4.3.3): each alternation
// group shows its drawn members one after another, each for `period` seconds.

#include <cstddef>
#include <map>
#include <vector>

#include "vicc_anatomy_viz/avatar_view/draw_state.hpp"

namespace vicc_anatomy_viz::avatar_view {

class AlternationCycle {
 public:
  /// `period_s` <= 0 or not finite: no cycling, each group shows its first member.
  AlternationCycle(const AvatarDrawState& state, double period_s);

  /// Whether state.items[item] is shown at `time_s` (items outside a group always are).
  bool shown(std::size_t item, double time_s) const;
  /// Changes exactly when some group switches member: redraw when it differs from the last.
  long step(double time_s) const;
  /// The members (indices into state.items) of each group that has more than one.
  const std::map<int, std::vector<std::size_t>>& groups() const { return members_; }

 private:
  double period_s_;
  std::vector<int> group_of_item_;
  std::map<int, std::vector<std::size_t>> members_;
};

}  // namespace vicc_anatomy_viz::avatar_view
