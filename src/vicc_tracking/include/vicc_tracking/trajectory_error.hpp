#pragma once
// Error of an estimated trajectory against ground truth. The tracker's map starts at its
// own first pose, so both are aligned at the first common stamp; the rest is drift.

#include <vector>

#include "vicc_tracking/tum_trajectory.hpp"

namespace vicc_tracking {

struct TrajectoryError {
  size_t matched = 0;          ///< estimated poses with a ground-truth pose at their stamp
  double rmse_position = 0.0;  ///< m
  double max_position = 0.0;   ///< m
  double max_rotation_deg = 0.0;
  double final_position = 0.0;  ///< m, at the last matched pose
  double final_rotation_deg = 0.0;
  /// T_truth_estimate: maps the estimate's map frame into the truth's (first matched pose).
  Eigen::Isometry3d alignment = Eigen::Isometry3d::Identity();
};

/// Poses are matched by stamp (within max_stamp_difference seconds).
TrajectoryError compareTrajectories(const std::vector<TimedPose>& estimate,
                                    const std::vector<TimedPose>& truth,
                                    double max_stamp_difference = 1e-4);

}  // namespace vicc_tracking
