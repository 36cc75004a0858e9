#pragma once
// The keys of a parameter table as paths ("ekf/process_noise_rotation"): for help texts and
// for the ROS readers' check of unknown keys when several tables share one namespace.

#include <set>
#include <string>

namespace vicc_common {

class ParameterNameCollector {
 public:
  explicit ParameterNameCollector(std::set<std::string>& names, std::string prefix = "")
      : names_(names), prefix_(std::move(prefix)) {}

  template <typename T>
  void operator()(const char* key, const T&) {
    names_.insert(prefix_ + key);
  }

  template <typename Config>
  void section(const char* key, const Config& config) {
    ParameterNameCollector nested(names_, prefix_ + key + "/");
    visitParameters(config, nested);
  }

 private:
  std::set<std::string>& names_;
  std::string prefix_;
};

/// Adds the key paths of `config`'s table to `names`.
template <typename Config>
void collectParameterNames(const Config& config, std::set<std::string>& names) {
  ParameterNameCollector collector(names);
  visitParameters(config, collector);
}

}  // namespace vicc_common
