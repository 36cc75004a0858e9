#include "vicc_tracking/trajectory_error.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "vicc_tracking/tracker.hpp"

namespace vicc_tracking {

TrajectoryError compareTrajectories(const std::vector<TimedPose>& estimate,
                                    const std::vector<TimedPose>& truth,
                                    double max_stamp_difference) {
  std::vector<TimedPose> sorted_truth = truth;
  std::sort(sorted_truth.begin(), sorted_truth.end(),
            [](const TimedPose& a, const TimedPose& b) { return a.stamp < b.stamp; });
  auto truthAt = [&](double stamp) -> const TimedPose* {
    auto it = std::lower_bound(sorted_truth.begin(), sorted_truth.end(), stamp,
                               [](const TimedPose& pose, double t) { return pose.stamp < t; });
    const TimedPose* best = nullptr;
    for (auto candidate : {it, it == sorted_truth.begin() ? it : std::prev(it)}) {
      if (candidate == sorted_truth.end()) continue;
      if (std::abs(candidate->stamp - stamp) > max_stamp_difference) continue;
      if (!best || std::abs(candidate->stamp - stamp) < std::abs(best->stamp - stamp)) {
        best = &*candidate;
      }
    }
    return best;
  };

  TrajectoryError error;
  std::optional<Eigen::Isometry3d> alignment;
  double squared_sum = 0.0;
  for (const TimedPose& pose : estimate) {
    const TimedPose* reference = truthAt(pose.stamp);
    if (!reference) continue;
    if (!alignment) alignment = reference->pose * pose.pose.inverse();
    const PoseDifference difference = poseDifference(reference->pose, *alignment * pose.pose);
    ++error.matched;
    squared_sum += difference.translation * difference.translation;
    error.max_position = std::max(error.max_position, difference.translation);
    error.max_rotation_deg = std::max(error.max_rotation_deg, difference.rotation_deg);
    error.final_position = difference.translation;
    error.final_rotation_deg = difference.rotation_deg;
  }
  if (alignment) error.alignment = *alignment;
  if (error.matched > 0) error.rmse_position = std::sqrt(squared_sum / error.matched);
  return error;
}

}  // namespace vicc_tracking
