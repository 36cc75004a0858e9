#include <memory>

#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>

#include "vicc_tracking/ros/tracker_ros.hpp"

namespace vicc_tracking {

class TrackerNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    // Single-threaded handles: the tracker's callbacks run one at a time.
    try {
      tracker_ = std::make_unique<TrackerRos>(getNodeHandle(), getPrivateNodeHandle());
    } catch (const std::exception& error) {
      NODELET_FATAL("tracker: %s", error.what());
      throw;
    }
  }
  std::unique_ptr<TrackerRos> tracker_;
};

}  // namespace vicc_tracking

PLUGINLIB_EXPORT_CLASS(vicc_tracking::TrackerNodelet, nodelet::Nodelet)
