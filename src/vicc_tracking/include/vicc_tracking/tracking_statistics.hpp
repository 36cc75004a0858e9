#pragma once
// Per-run statistics over FrameReports, in the terms of thesis 5.5.1: failures, ICP
// iterations (mean ± std), the initial-guess quality ratio Init_EKF / Init_Id, loop-closure
// drift, and stage timings. Shared by vicc_reconstruct and the benchmark.

#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "vicc_tracking/tracker.hpp"

namespace vicc_tracking {

struct SampleSummary {
  size_t count = 0;
  double mean = 0.0;
  double stddev = 0.0;  ///< population standard deviation
  double median = 0.0;
};
SampleSummary summarize(std::vector<double> values);

class TrackingStatistics {
 public:
  /// Frames whose identity error is below these are left out of the Init ratio: the
  /// camera did not move, the ratio is noise / noise.
  explicit TrackingStatistics(double min_motion_position = 1e-3,
                              double min_motion_rotation_deg = 0.1);

  void add(const FrameReport& report);

  int framesSeen() const { return frames_seen_; }
  int framesDropped() const { return frames_dropped_; }
  int framesInitializing() const { return frames_initializing_; }
  int framesTracked() const { return frames_tracked_; }
  int framesLost() const { return frames_lost_; }

  SampleSummary iterations() const { return summarize(iterations_); }
  SampleSummary initRatioPosition() const { return summarize(ratio_position_); }
  SampleSummary initRatioRotation() const { return summarize(ratio_rotation_); }
  SampleSummary preprocessingMs() const { return summarize(preprocessing_ms_); }
  SampleSummary predictionMs() const { return summarize(prediction_ms_); }
  SampleSummary icpMs() const { return summarize(icp_ms_); }
  SampleSummary totalMs() const { return summarize(total_ms_); }

  /// First and last tracked camera pose; on a closed loop their difference is the drift.
  std::optional<Eigen::Isometry3d> firstPose() const { return first_pose_; }
  std::optional<Eigen::Isometry3d> lastPose() const { return last_pose_; }
  std::optional<PoseDifference> loopClosureDrift() const;

 private:
  double min_motion_position_;
  double min_motion_rotation_deg_;
  int frames_seen_ = 0;
  int frames_dropped_ = 0;
  int frames_initializing_ = 0;
  int frames_tracked_ = 0;
  int frames_lost_ = 0;
  std::vector<double> iterations_;
  std::vector<double> ratio_position_;
  std::vector<double> ratio_rotation_;
  std::vector<double> preprocessing_ms_;
  std::vector<double> prediction_ms_;
  std::vector<double> icp_ms_;
  std::vector<double> total_ms_;
  std::optional<Eigen::Isometry3d> first_pose_;
  std::optional<Eigen::Isometry3d> last_pose_;
};

}  // namespace vicc_tracking
