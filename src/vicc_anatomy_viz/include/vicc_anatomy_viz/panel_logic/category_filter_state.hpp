#pragma once
// The patient panel's category filter (thesis Fig. 4.7A): which categories of the view the
// avatar hides. The view's categories come from the legend of a published EncodedStatus; hidden
// ids are remembered across legends, but only those of the current view are requested (the
// server rejects a filter naming a category the view does not have).

#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace vicc_anatomy_viz::panel {

struct CategoryItem {
  std::string id;
  std::string label;
  std::uint32_t count = 0;  ///< structures carrying the category in the status shown
  float red = 0.f, green = 0.f, blue = 0.f;  ///< the category's hue at its strongest level
};

class CategoryFilterState {
 public:
  void setLegend(std::vector<CategoryItem> legend);
  bool legendKnown() const { return legend_known_; }
  const std::vector<CategoryItem>& legend() const { return legend_; }

  void setVisible(const std::string& id, bool visible);
  bool isVisible(const std::string& id) const { return hidden_.count(id) == 0; }
  /// Replaces the hidden set (a restored configuration, or the filter the server applied).
  void setHidden(const std::vector<std::string>& hidden);

  /// The filter to request: hidden ids of the current legend in legend order; before a legend is
  /// known, every remembered id (sorted).
  std::vector<std::string> requestedHidden() const;
  /// Remembered hidden ids the current legend does not have (reported, not requested).
  std::vector<std::string> unknownHidden() const;
  /// Every remembered hidden id, sorted (what the configuration saves).
  std::vector<std::string> allHidden() const { return {hidden_.begin(), hidden_.end()}; }

 private:
  bool inLegend(const std::string& id) const;

  std::vector<CategoryItem> legend_;
  bool legend_known_ = false;
  std::set<std::string> hidden_;
};

/// `hidden` without the ids that are not in `known` (order kept).
std::vector<std::string> keepKnownCategories(const std::vector<std::string>& hidden,
                                             const std::vector<std::string>& known);

}  // namespace vicc_anatomy_viz::panel
