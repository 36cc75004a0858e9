#pragma once
// A config section (IcpConfig, EkfConfig, SurfelFusionConfig) and its dynamic_reconfigure
// .cfg meet by key: every .cfg parameter is the section table's field of the same name and
// type (parameter_types.hpp), so the conversions between the generated XxxConfig and the
// section walk the table instead of copying field by field. Fields the .cfg leaves out keep
// the section's values. A .cfg parameter the table lacks, or whose type differs from the
// table's, is a std::logic_error naming it (the unit tests convert every shipped .cfg).

#include <set>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <dynamic_reconfigure/Config.h>

#include "vicc_common/parameter_types.hpp"

namespace vicc_tracking {
namespace reconfigure_table {

/// "double", "int", "bool" or "str" for the message list `key` is in; "" if in none.
std::string typeInMessage(const dynamic_reconfigure::Config& message, const std::string& key);
/// Throws std::logic_error unless `cfg_type` is `table_type`.
void expectSameType(const std::string& key, const std::string& cfg_type, const char* table_type);
/// Throws std::logic_error naming the first parameter of `message` not in `covered`.
void expectAllCovered(const dynamic_reconfigure::Config& message,
                      const std::set<std::string>& covered);

/// A value a .cfg parameter holds as it is (the others are lists, or types stored as text).
template <typename T>
constexpr bool kIsCfgScalar = std::is_same_v<T, double> || std::is_same_v<T, int> ||
                              std::is_same_v<T, bool> || std::is_same_v<T, std::string>;
template <typename T>
constexpr bool kIsText = !vicc_common::IsPlainParameter<T>::value;

/// The .cfg type a table field of type T has ("" for lists, which a .cfg cannot hold).
template <typename T>
const char* cfgTypeOf() {
  if constexpr (std::is_same_v<T, double>) return "double";
  if constexpr (std::is_same_v<T, int>) return "int";
  if constexpr (std::is_same_v<T, bool>) return "bool";
  if constexpr (std::is_same_v<T, std::string> || kIsText<T>) return "str";
  return "";
}

/// The message entry named `key` in the list for T.
template <typename T, typename Message>
auto& entryOf(Message& message, const std::string& key) {
  auto find = [&](auto& entries) -> auto& {
    for (auto& entry : entries)
      if (entry.name == key) return entry;
    throw std::logic_error("dynamic_reconfigure parameter '" + key + "' vanished");
  };
  if constexpr (std::is_same_v<T, double>) {
    return find(message.doubles);
  } else if constexpr (std::is_same_v<T, int>) {
    return find(message.ints);
  } else if constexpr (std::is_same_v<T, bool>) {
    return find(message.bools);
  } else {
    return find(message.strs);
  }
}

/// Table visitor: the section's values into a message that holds every .cfg parameter.
class MessageWriter {
 public:
  MessageWriter(dynamic_reconfigure::Config& message, std::set<std::string>& covered)
      : message_(message), covered_(covered) {}

  template <typename T>
  void operator()(const char* key, const T& field) {
    const std::string cfg_type = typeInMessage(message_, key);
    if (cfg_type.empty()) return;                   // a start-up parameter, not tuned while running
    expectSameType(key, cfg_type, cfgTypeOf<T>());  // lists end here
    if constexpr (kIsCfgScalar<T>) {
      entryOf<T>(message_, key).value = field;
    } else if constexpr (kIsText<T>) {
      entryOf<std::string>(message_, key).value = toParameterText(field);
    }
    covered_.insert(key);
  }
  template <typename Config>
  void section(const char*, const Config&) {}  // nested sections have servers of their own

 private:
  dynamic_reconfigure::Config& message_;
  std::set<std::string>& covered_;
};

/// Table visitor: the message's values into the section's fields of the same names.
class MessageReader {
 public:
  explicit MessageReader(const dynamic_reconfigure::Config& message) : message_(message) {}

  template <typename T>
  void operator()(const char* key, T& field) const {
    const std::string cfg_type = typeInMessage(message_, key);
    if (cfg_type.empty()) return;
    expectSameType(key, cfg_type, cfgTypeOf<T>());  // lists end here
    if constexpr (std::is_same_v<T, bool>) {
      field = entryOf<bool>(message_, key).value != 0;  // a uint8 in the message
    } else if constexpr (kIsCfgScalar<T>) {
      field = entryOf<T>(message_, key).value;
    } else if constexpr (kIsText<T>) {
      fromParameterText(entryOf<std::string>(message_, key).value, field);
    }
  }
  template <typename Config>
  void section(const char*, Config&) const {}

 private:
  const dynamic_reconfigure::Config& message_;
};

}  // namespace reconfigure_table

/// The generated `Tuning` (e.g. IcpTuningConfig) holding `section`'s values of its parameters.
template <typename Tuning, typename Section>
Tuning toTuning(const Section& section) {
  dynamic_reconfigure::Config message;
  Tuning::__getDefault__().__toMessage__(message);
  std::set<std::string> covered;
  reconfigure_table::MessageWriter writer(message, covered);
  visitParameters(section, writer);
  reconfigure_table::expectAllCovered(message, covered);
  Tuning tuning = Tuning::__getDefault__();
  tuning.__fromMessage__(message);
  return tuning;
}

/// `base` with the values of `tuning`'s parameters; its other fields unchanged.
template <typename Tuning, typename Section>
Section fromTuning(const Tuning& tuning, Section base) {
  dynamic_reconfigure::Config message;
  tuning.__toMessage__(message);
  const reconfigure_table::MessageReader reader(message);
  visitParameters(base, reader);
  return base;
}

}  // namespace vicc_tracking
