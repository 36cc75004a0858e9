#include <memory>

#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>

#include "vicc_fusion/ros/fusion_ros.hpp"

namespace vicc_fusion {

/// In a manager with the camera driver, depth images arrive as shared pointers: tracking,
/// fusion and model prediction all work on them without a copy.
class FusionNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    try {
      fusion_ = std::make_unique<FusionRos>(getNodeHandle(), getPrivateNodeHandle());
    } catch (const std::exception& error) {
      NODELET_FATAL("fusion: %s", error.what());
      throw;
    }
  }
  std::unique_ptr<FusionRos> fusion_;
};

}  // namespace vicc_fusion

PLUGINLIB_EXPORT_CLASS(vicc_fusion::FusionNodelet, nodelet::Nodelet)
