#pragma once
// Parameter tables (parameter_types.hpp) read from a ros::NodeHandle: every key is optional, a
// value of the wrong type throws std::invalid_argument naming the parameter and the expected
// type (never the silent default of NodeHandle::param), each section is validated. The names
// read are remembered, so that parameters in the node's namespace no table knows (typos)
// can be named in a warning.

#include <set>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <ros/node_handle.h>

#include "vicc_common/parameter_types.hpp"

namespace vicc_common {

/// 'value' / "a list" / "a section" ... of the parameter server's value at `name`.
std::string describeRosParameter(const ros::NodeHandle& nh, const std::string& name);

class RosParameterReader {
 public:
  /// `read_names` collects the resolved names of the keys the tables asked for.
  RosParameterReader(const ros::NodeHandle& nh, std::set<std::string>& read_names)
      : nh_(nh), read_names_(read_names) {}

  template <typename T>
  void operator()(const char* key, T& field) {
    read_names_.insert(nh_.resolveName(key));
    if (!nh_.hasParam(key)) return;
    if constexpr (IsPlainParameter<T>::value) {
      readPlain(key, field);
    } else {
      std::string text;
      readPlain(key, text);
      try {
        fromParameterText(text, field);
      } catch (const std::exception& error) {
        throw std::invalid_argument("parameter " + nh_.resolveName(key) + ": " + error.what());
      }
    }
  }

  template <typename Config>
  void section(const char* key, Config& config) {
    const ros::NodeHandle section_nh(nh_, key);
    RosParameterReader reader(section_nh, read_names_);
    visitParameters(config, reader);
    reader.validate(config);
  }

  /// validate() of the struct read at this reader's namespace, its message prefixed with it.
  template <typename Config>
  void validate(const Config& config) const {
    try {
      validateIfDefined(config);
    } catch (const std::exception& error) {
      throw std::invalid_argument("parameters under " + nh_.getNamespace() + ": " + error.what());
    }
  }

 private:
  template <typename T>
  void readPlain(const char* key, T& field) const {
    if constexpr (std::is_same_v<T, int>) {
      // roscpp's getParam(int&) rounds a double (2.5 -> 3) and wraps one beyond int's range:
      // an integer parameter must be an XML-RPC integer.
      XmlRpc::XmlRpcValue raw;
      if (nh_.getParam(key, raw) && raw.getType() == XmlRpc::XmlRpcValue::TypeInt) {
        field = static_cast<int>(raw);
        return;
      }
      throw std::invalid_argument("parameter " + nh_.resolveName(key) +
                                  " has the wrong type: expected " + expectedTypeName<T>() +
                                  ", got " + describeRosParameter(nh_, key));
    }
    T value{};
    if (!nh_.getParam(key, value)) {
      throw std::invalid_argument("parameter " + nh_.resolveName(key) +
                                  " has the wrong type: expected " + expectedTypeName<T>() +
                                  ", got " + describeRosParameter(nh_, key));
    }
    field = value;
  }

  const ros::NodeHandle nh_;
  std::set<std::string>& read_names_;
};

/// Reads `config` from the parameters under `nh` and validates it; adds the names it asked for
/// to `read_names`.
template <typename Config>
void readRosParameters(const ros::NodeHandle& nh, Config& config,
                       std::set<std::string>& read_names) {
  RosParameterReader reader(nh, read_names);
  visitParameters(config, reader);
  reader.validate(config);
}

/// The parameters under `nh`'s namespace whose names are not in `known` (resolved names),
/// leaving out those under `foreign` (resolved namespaces another library keeps its
/// parameters in, e.g. an image_transport publisher's).
std::vector<std::string> unknownRosParameters(const ros::NodeHandle& nh,
                                              const std::set<std::string>& known,
                                              const std::vector<std::string>& foreign = {});

/// ROS_WARN naming the unknown parameters under `nh` (they are ignored); returns them.
std::vector<std::string> warnUnknownRosParameters(const ros::NodeHandle& nh,
                                                  const std::set<std::string>& known,
                                                  const std::vector<std::string>& foreign = {});

}  // namespace vicc_common
