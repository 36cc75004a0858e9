#pragma once
// Parameter tables (parameter_types.hpp) written as JSON (nlohmann::json), for reports that
// record the parameters a run used. Header-only: the includer links nlohmann_json.

#include <nlohmann/json.hpp>

#include "vicc_common/parameter_types.hpp"

namespace vicc_common {

class JsonParameterWriter {
 public:
  explicit JsonParameterWriter(nlohmann::json& out) : out_(out) {}

  template <typename T>
  void operator()(const char* key, const T& value) {
    if constexpr (IsPlainParameter<T>::value) {
      out_[key] = value;
    } else {
      out_[key] = toParameterText(value);
    }
  }

  template <typename Config>
  void section(const char* key, const Config& config) {
    JsonParameterWriter writer(out_[key]);
    visitParameters(config, writer);
  }

 private:
  nlohmann::json& out_;
};

/// Writes `config`'s table into `out` (an object; existing keys of `out` stay).
template <typename Config>
void writeJsonParameters(const Config& config, nlohmann::json& out) {
  JsonParameterWriter writer(out);
  visitParameters(config, writer);
}

}  // namespace vicc_common
