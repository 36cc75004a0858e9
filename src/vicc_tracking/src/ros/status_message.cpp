#include "vicc_tracking/ros/status_message.hpp"

namespace vicc_tracking {

vicc_msgs::TrackingStatus statusMessage(const FrameReport& report, InitStrategyType strategy) {
  vicc_msgs::TrackingStatus status;
  switch (report.state) {
    case TrackingState::kInitializing:
      status.state = vicc_msgs::TrackingStatus::STATE_INITIALIZING;
      break;
    case TrackingState::kOk:
      status.state = vicc_msgs::TrackingStatus::STATE_OK;
      break;
    case TrackingState::kLost:
      status.state = vicc_msgs::TrackingStatus::STATE_LOST;
      status.failure_reason = report.message;
      break;
  }
  status.frame_index = static_cast<uint32_t>(std::max(report.frame_index, 0));
  status.init_strategy = toString(strategy);
  status.iterations = static_cast<uint32_t>(report.icp.iterations);
  for (const int iterations : report.icp.iterations_per_level) {
    status.iterations_per_level.push_back(static_cast<uint32_t>(iterations));
  }
  status.inliers = static_cast<uint32_t>(report.icp.inliers);
  status.inlier_ratio = static_cast<float>(report.icp.inlier_ratio);
  status.residual_rms = static_cast<float>(report.icp.residual_rms);
  status.condition_number = static_cast<float>(report.icp.condition_number);
  status.init_error_position = static_cast<float>(report.init_error_position);
  status.init_error_rotation = static_cast<float>(report.init_error_rotation_deg);
  status.preprocessing_ms = static_cast<float>(report.timings.preprocessing_ms);
  status.prediction_ms = static_cast<float>(report.timings.prediction_ms);
  status.icp_ms = static_cast<float>(report.timings.icp_ms);
  status.total_ms = static_cast<float>(report.timings.total_ms);
  return status;
}

}  // namespace vicc_tracking
