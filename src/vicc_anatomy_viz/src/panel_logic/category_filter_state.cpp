#include "vicc_anatomy_viz/panel_logic/category_filter_state.hpp"

#include <algorithm>

namespace vicc_anatomy_viz::panel {

void CategoryFilterState::setLegend(std::vector<CategoryItem> legend) {
  legend_ = std::move(legend);
  legend_known_ = true;
}

void CategoryFilterState::setVisible(const std::string& id, bool visible) {
  if (visible) {
    hidden_.erase(id);
  } else {
    hidden_.insert(id);
  }
}

void CategoryFilterState::setHidden(const std::vector<std::string>& hidden) {
  hidden_ = std::set<std::string>(hidden.begin(), hidden.end());
}

bool CategoryFilterState::inLegend(const std::string& id) const {
  return std::any_of(legend_.begin(), legend_.end(),
                     [&](const CategoryItem& item) { return item.id == id; });
}

std::vector<std::string> CategoryFilterState::requestedHidden() const {
  if (!legend_known_) return allHidden();
  std::vector<std::string> requested;
  for (const auto& item : legend_) {
    if (hidden_.count(item.id)) requested.push_back(item.id);
  }
  return requested;
}

std::vector<std::string> CategoryFilterState::unknownHidden() const {
  std::vector<std::string> unknown;
  if (!legend_known_) return unknown;
  for (const auto& id : hidden_) {
    if (!inLegend(id)) unknown.push_back(id);
  }
  return unknown;
}

std::vector<std::string> keepKnownCategories(const std::vector<std::string>& hidden,
                                             const std::vector<std::string>& known) {
  std::vector<std::string> kept;
  for (const auto& id : hidden) {
    if (std::find(known.begin(), known.end(), id) != known.end()) kept.push_back(id);
  }
  return kept;
}

}  // namespace vicc_anatomy_viz::panel
