#pragma once
// What a parameter table may hold, shared by every reader and writer of the tables.
//
// A config struct publishes its keys with a free function found by argument-dependent lookup:
//   template <typename Config, typename Visitor>
//   void visitParameters(Config& config, Visitor& visit);   // Config may be const (writers)
// calling visit(key, field) for a value and visit.section(key, sub_config) for a nested
// section. A value is one of the plain types below or a type stored as text (an enum): for
// those, the type's namespace provides
//   std::string toParameterText(const T& value);
//   void fromParameterText(const std::string& text, T& value);  // throws with the reason
// Every struct that has validate() is validated after its keys are read.

#include <string>
#include <type_traits>
#include <vector>

namespace vicc_common {

template <typename T>
struct IsPlainParameter : std::false_type {};
template <>
struct IsPlainParameter<int> : std::true_type {};
template <>
struct IsPlainParameter<double> : std::true_type {};
template <>
struct IsPlainParameter<bool> : std::true_type {};
template <>
struct IsPlainParameter<std::string> : std::true_type {};
template <>
struct IsPlainParameter<std::vector<int>> : std::true_type {};
template <>
struct IsPlainParameter<std::vector<double>> : std::true_type {};
template <>
struct IsPlainParameter<std::vector<std::string>> : std::true_type {};

/// "an integer", "a number", ...: the words of the wrong-type messages.
template <typename T>
const char* expectedTypeName() {
  if constexpr (std::is_same_v<T, int>) return "an integer";
  if constexpr (std::is_same_v<T, double>) return "a number";
  if constexpr (std::is_same_v<T, bool>) return "true or false";
  if constexpr (std::is_same_v<T, std::string>) return "a string";
  if constexpr (std::is_same_v<T, std::vector<int>>) return "a list of integers";
  if constexpr (std::is_same_v<T, std::vector<double>>) return "a list of numbers";
  if constexpr (std::is_same_v<T, std::vector<std::string>>) return "a list of strings";
  return "a string";  // types stored as text
}

template <typename Config, typename = void>
struct HasValidate : std::false_type {};
template <typename Config>
struct HasValidate<Config, std::void_t<decltype(std::declval<const Config&>().validate())>>
    : std::true_type {};

/// Calls config.validate() if the struct has one.
template <typename Config>
void validateIfDefined(const Config& config) {
  if constexpr (HasValidate<Config>::value) config.validate();
}

}  // namespace vicc_common
