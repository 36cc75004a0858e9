#include "vicc_tracking/tracking_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace vicc_tracking {

SampleSummary summarize(std::vector<double> values) {
  SampleSummary summary;
  summary.count = values.size();
  if (values.empty()) return summary;
  summary.mean = std::accumulate(values.begin(), values.end(), 0.0) / values.size();
  double squares = 0.0;
  for (const double value : values) squares += (value - summary.mean) * (value - summary.mean);
  summary.stddev = std::sqrt(squares / values.size());
  const size_t middle = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + middle, values.end());
  summary.median = values[middle];
  if (values.size() % 2 == 0) {
    const double lower = *std::max_element(values.begin(), values.begin() + middle);
    summary.median = 0.5 * (summary.median + lower);
  }
  return summary;
}

TrackingStatistics::TrackingStatistics(double min_motion_position, double min_motion_rotation_deg)
    : min_motion_position_(min_motion_position),
      min_motion_rotation_deg_(min_motion_rotation_deg) {}

void TrackingStatistics::add(const FrameReport& report) {
  ++frames_seen_;
  if (!report.accepted) {
    ++frames_dropped_;
    return;
  }
  preprocessing_ms_.push_back(report.timings.preprocessing_ms);
  if (report.state == TrackingState::kInitializing) {
    ++frames_initializing_;
    return;
  }
  prediction_ms_.push_back(report.timings.prediction_ms);
  icp_ms_.push_back(report.timings.icp_ms);
  total_ms_.push_back(report.timings.total_ms);
  if (report.state == TrackingState::kLost) {
    ++frames_lost_;
    return;
  }
  ++frames_tracked_;
  if (!first_pose_) first_pose_ = report.camera_pose;
  last_pose_ = report.camera_pose;
  // The first tracked frame has no ICP run (it starts the map).
  if (report.icp.iterations > 0) iterations_.push_back(report.icp.iterations);
  if (report.identity_error_position > min_motion_position_) {
    ratio_position_.push_back(report.init_error_position / report.identity_error_position);
  }
  if (report.identity_error_rotation_deg > min_motion_rotation_deg_) {
    ratio_rotation_.push_back(report.init_error_rotation_deg / report.identity_error_rotation_deg);
  }
}

std::optional<PoseDifference> TrackingStatistics::loopClosureDrift() const {
  if (!first_pose_ || !last_pose_) return std::nullopt;
  return poseDifference(*first_pose_, *last_pose_);
}

}  // namespace vicc_tracking
