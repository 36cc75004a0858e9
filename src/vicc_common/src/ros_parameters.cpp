#include "vicc_common/ros_parameters.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>

#include <ros/console.h>
#include <ros/param.h>

namespace vicc_common {

std::string describeRosParameter(const ros::NodeHandle& nh, const std::string& name) {
  XmlRpc::XmlRpcValue value;
  if (!nh.getParam(name, value)) return "no value";
  switch (value.getType()) {
    case XmlRpc::XmlRpcValue::TypeBoolean:
      return std::string("'") + (static_cast<bool>(value) ? "true" : "false") + "'";
    case XmlRpc::XmlRpcValue::TypeInt:
      return "'" + std::to_string(static_cast<int>(value)) + "'";
    case XmlRpc::XmlRpcValue::TypeDouble: {
      std::ostringstream text;  // shortest form with 15 digits: 2.5, 99999999999, 1e-07
      text << std::setprecision(15) << static_cast<double>(value);
      return "'" + text.str() + "'";
    }
    case XmlRpc::XmlRpcValue::TypeString:
      return "'" + static_cast<std::string>(value) + "'";
    case XmlRpc::XmlRpcValue::TypeArray:
      return "a list";
    case XmlRpc::XmlRpcValue::TypeStruct:
      return "a section";
    default:
      return "a value of another type";
  }
}

namespace {

bool isUnder(const std::string& name, const std::string& ns) {
  const std::string prefix = ns == "/" ? "/" : ns + "/";
  return name.compare(0, prefix.size(), prefix) == 0;
}

}  // namespace

std::vector<std::string> unknownRosParameters(const ros::NodeHandle& nh,
                                              const std::set<std::string>& known,
                                              const std::vector<std::string>& foreign) {
  std::vector<std::string> all_names;
  std::vector<std::string> unknown;
  if (!ros::param::getParamNames(all_names)) return unknown;  // no master: nothing to check
  for (const std::string& name : all_names) {
    if (!isUnder(name, nh.getNamespace()) || known.count(name) > 0) continue;
    const bool foreign_name = std::any_of(foreign.begin(), foreign.end(),
                                          [&](const std::string& ns) { return isUnder(name, ns); });
    if (!foreign_name) unknown.push_back(name);
  }
  std::sort(unknown.begin(), unknown.end());
  return unknown;
}

std::vector<std::string> warnUnknownRosParameters(const ros::NodeHandle& nh,
                                                  const std::set<std::string>& known,
                                                  const std::vector<std::string>& foreign) {
  const std::vector<std::string> unknown = unknownRosParameters(nh, known, foreign);
  if (unknown.empty()) return unknown;
  std::string names;
  for (const std::string& name : unknown) names += (names.empty() ? "" : ", ") + name;
  ROS_WARN("unknown parameters under %s, ignored (a typo?): %s", nh.getNamespace().c_str(),
           names.c_str());
  return unknown;
}

}  // namespace vicc_common
