#pragma once
// Step 4 of the three-level mapping (thesis 4.3.2.3): property values -> levels of the
// property's visual variable. Detects property-domain non-injectivity (quantization, 4.3.2.4).

#include <string>
#include <vector>

#include "vicc_anatomy_viz/data_model.hpp"
#include "vicc_anatomy_viz/visual_variables.hpp"

namespace vicc_anatomy_viz {

class LevelMapping {
 public:
  /// Throws ConfigError naming category.property when the levels cannot be realised (more
  /// levels than the variable distinguishes, thresholds outside the domain or unsorted).
  LevelMapping(const Category& category, const Property& property, const VisualVariable& variable);

  /// Number of distinct visual levels used.
  int levelCount() const { return level_count_; }
  /// Number of values that are displayed (abnormal ones, plus normal ones for
  /// contralateral comparison).
  int displayedValueCount() const { return static_cast<int>(displayed_.size()); }
  /// More displayed values than levels: information is lost and must be reported.
  bool quantized() const { return displayedValueCount() > level_count_; }
  /// Level 1..levelCount() of a displayed value; 0 for a value that is not displayed.
  int levelOf(const Value& value) const;
  /// The displayed values that share `level` (e.g. pain 7..10 for level 3).
  std::vector<Value> valuesAtLevel(int level) const;

 private:
  std::vector<Value> displayed_;
  std::vector<int> thresholds_;
  int level_count_ = 0;
};

}  // namespace vicc_anatomy_viz
