#include "vicc_anatomy_viz/level_mapping.hpp"

#include <algorithm>

#include "vicc_anatomy_viz/errors.hpp"

namespace vicc_anatomy_viz {

LevelMapping::LevelMapping(const Category& category, const Property& property,
                           const VisualVariable& variable) {
  const std::string where = "category '" + category.id + "', property '" + property.prop_type + "'";
  // Normal values are not displayed (DG5), unless the category compares both sides: then a
  // normal value next to an abnormal contralateral one must be visible too.
  for (const Value& value : property.domain.values()) {
    if (category.compare_contralateral || !property.isNormal(value)) displayed_.push_back(value);
  }
  if (displayed_.empty()) {
    throw ConfigError(where + ": every value of the domain is normal, nothing can be displayed");
  }
  const int values = static_cast<int>(displayed_.size());
  const int range = variable.distinguishableValues();
  if (!property.thresholds.empty()) {
    thresholds_ = property.thresholds;
    for (std::size_t i = 1; i < thresholds_.size(); ++i) {
      if (thresholds_[i] <= thresholds_[i - 1]) {
        throw ConfigError(where + ": thresholds must be strictly increasing");
      }
    }
    const int first = displayed_.front().asNumber();
    const int last = displayed_.back().asNumber();
    if (thresholds_.front() <= first || thresholds_.back() > last) {
      throw ConfigError(where + ": thresholds must lie within " + std::to_string(first + 1) + ".." +
                        std::to_string(last) + " so that every level holds a value");
    }
    level_count_ = static_cast<int>(thresholds_.size()) + 1;
  } else if (property.levels > 0) {
    if (property.levels > values) {
      throw ConfigError(where + ": " + std::to_string(property.levels) + " levels for only " +
                        std::to_string(values) + " displayed values");
    }
    level_count_ = property.levels;
  } else {
    level_count_ = std::min(values, range);
  }
  if (level_count_ > range) {
    throw ConfigError(where + ": " + std::to_string(level_count_) +
                      " levels, but visual variable '" + variable.id + "' distinguishes only " +
                      std::to_string(range));
  }
}

int LevelMapping::levelOf(const Value& value) const {
  const auto it = std::find(displayed_.begin(), displayed_.end(), value);
  if (it == displayed_.end()) return 0;
  if (!thresholds_.empty()) {
    const int number = value.asNumber();
    return 1 + static_cast<int>(std::count_if(thresholds_.begin(), thresholds_.end(),
                                              [number](int t) { return t <= number; }));
  }
  // Even split of the displayed values over the levels, in domain order.
  const int index = static_cast<int>(it - displayed_.begin());
  return index * level_count_ / displayedValueCount() + 1;
}

std::vector<Value> LevelMapping::valuesAtLevel(int level) const {
  std::vector<Value> out;
  for (const auto& value : displayed_) {
    if (levelOf(value) == level) out.push_back(value);
  }
  return out;
}

}  // namespace vicc_anatomy_viz
