#include "vicc_tracking/ros/reconfigurable_section.hpp"

#include <sstream>
#include <type_traits>

namespace vicc_tracking {
namespace {

template <typename Parameter>
void appendChanges(const std::vector<Parameter>& requested, const std::vector<Parameter>& current,
                   std::ostringstream& out) {
  for (const Parameter& entry : requested) {
    for (const Parameter& old : current) {
      if (old.name != entry.name || old.value == entry.value) continue;
      out << (out.tellp() > 0 ? ", " : "") << entry.name << "=";
      if constexpr (std::is_same_v<Parameter, dynamic_reconfigure::BoolParameter>) {
        out << (entry.value ? "true" : "false");  // a uint8_t would print as a character
      } else {
        out << entry.value;
      }
    }
  }
}

}  // namespace

std::string describeChanges(const dynamic_reconfigure::Config& request,
                            const dynamic_reconfigure::Config& current) {
  std::ostringstream out;
  out.precision(12);
  appendChanges(request.doubles, current.doubles, out);
  appendChanges(request.ints, current.ints, out);
  appendChanges(request.bools, current.bools, out);
  appendChanges(request.strs, current.strs, out);
  return out.str();
}

}  // namespace vicc_tracking
