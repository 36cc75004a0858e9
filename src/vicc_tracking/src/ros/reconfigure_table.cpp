#include "vicc_tracking/ros/reconfigure_table.hpp"

namespace vicc_tracking::reconfigure_table {
namespace {

template <typename Parameter>
bool contains(const std::vector<Parameter>& entries, const std::string& key) {
  for (const Parameter& entry : entries)
    if (entry.name == key) return true;
  return false;
}

}  // namespace

std::string typeInMessage(const dynamic_reconfigure::Config& message, const std::string& key) {
  if (contains(message.doubles, key)) return "double";
  if (contains(message.ints, key)) return "int";
  if (contains(message.bools, key)) return "bool";
  if (contains(message.strs, key)) return "str";
  return "";
}

void expectSameType(const std::string& key, const std::string& cfg_type, const char* table_type) {
  if (cfg_type == table_type) return;
  throw std::logic_error("dynamic_reconfigure parameter '" + key + "' is " + cfg_type +
                         "_t in the .cfg but " + (*table_type ? table_type : "a list") +
                         " in the parameter table");
}

void expectAllCovered(const dynamic_reconfigure::Config& message,
                      const std::set<std::string>& covered) {
  auto check = [&](const auto& entries) {
    for (const auto& entry : entries) {
      if (!covered.count(entry.name)) {
        throw std::logic_error("dynamic_reconfigure parameter '" + entry.name +
                               "' is no key of the section's parameter table");
      }
    }
  };
  check(message.doubles);
  check(message.ints);
  check(message.bools);
  check(message.strs);
}

}  // namespace vicc_tracking::reconfigure_table
