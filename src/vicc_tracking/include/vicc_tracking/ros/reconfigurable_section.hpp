#pragma once
// One config section (IcpConfig, EkfConfig, SurfelFusionConfig, ...) served by a
// dynamic_reconfigure server in its own namespace (~icp, ~ekf, ~fusion: the sections of the
// parameter files, so the server's names are the parameter keys). A request is checked by the
// section's validate(); an invalid one is refused with a warning naming the requested values and
// the reason, and the server reports the old values back. Accepted values wait under a mutex
// until the node takes them between two frames: the reconfigure service may run on another
// thread than the frame callbacks (nodelet managers, multi-threaded spinners).
//
// The .cfg's parameters are the section table's keys (reconfigure_table.hpp): the table drives
// the conversions, found for the section by argument-dependent lookup (visitParameters).

#include <mutex>
#include <optional>
#include <string>
#include <utility>

#include <dynamic_reconfigure/Config.h>
#include <dynamic_reconfigure/server.h>
#include <ros/ros.h>
#include <boost/thread/recursive_mutex.hpp>

#include "vicc_tracking/ros/reconfigure_table.hpp"

namespace vicc_tracking {

/// "name=value" for every value of `request` that differs from `current`.
std::string describeChanges(const dynamic_reconfigure::Config& request,
                            const dynamic_reconfigure::Config& current);

template <typename Section, typename Tuning>
class ReconfigurableSection {
 public:
  /// Serves `initial` (the values the node runs with) on `nh`; `label` starts its log lines.
  ReconfigurableSection(const ros::NodeHandle& nh, std::string label, const Section& initial)
      : label_(std::move(label)), accepted_(initial), server_(server_mutex_, nh) {
    Tuning tuning = toTuning<Tuning>(initial);
    server_.updateConfig(tuning);
    // setCallback replays the initial values: no change, nothing to apply.
    server_.setCallback([this](Tuning& request, uint32_t) { onRequest(request); });
  }

  /// The accepted section if a request changed it since the last call.
  std::optional<Section> takeChange() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!changed_) return std::nullopt;
    changed_ = false;
    return accepted_;
  }

 private:
  void onRequest(Tuning& request) {
    std::lock_guard<std::mutex> lock(mutex_);
    const Tuning current = toTuning<Tuning>(accepted_);
    dynamic_reconfigure::Config requested_values, current_values;
    request.__toMessage__(requested_values);
    current.__toMessage__(current_values);
    const std::string changes = describeChanges(requested_values, current_values);
    if (changes.empty()) return;
    const Section candidate = fromTuning(request, accepted_);
    try {
      candidate.validate();
    } catch (const std::exception& error) {
      ROS_WARN("%s: dynamic_reconfigure request %s refused, old values kept: %s", label_.c_str(),
               changes.c_str(), error.what());
      request = current;  // the server answers and publishes the values still in use
      return;
    }
    accepted_ = candidate;
    changed_ = true;
    ROS_INFO("%s: dynamic_reconfigure set %s", label_.c_str(), changes.c_str());
  }

  const std::string label_;
  std::mutex mutex_;
  Section accepted_;
  bool changed_ = false;
  boost::recursive_mutex server_mutex_;  ///< held by the server around onRequest
  dynamic_reconfigure::Server<Tuning> server_;
};

}  // namespace vicc_tracking
