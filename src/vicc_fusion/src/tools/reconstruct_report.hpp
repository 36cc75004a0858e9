#pragma once
// The JSON report of vicc_reconstruct.

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "reconstruct_options.hpp"
#include "vicc_fusion/model_accuracy.hpp"
#include "vicc_tracking/tracking_statistics.hpp"
#include "vicc_tracking/trajectory_error.hpp"

namespace vicc_fusion {

struct ReconstructRun {
  std::string depth_topic, info_topic, imu_topic;
  std::string intensity_topic;       ///< empty: none
  int frames_with_intensity = 0;     ///< fused with their gray image
  int frames_without_intensity = 0;  ///< fused without (no gray image of their stamp, or bad)
  /// Share of the stable surfels that carry an intensity (fusion ran).
  double stable_with_intensity = 0.0;
  size_t depth_frames_in_bag = 0;
  size_t depth_frames_skipped = 0;  ///< by --frame-step
  double wall_time_s = 0.0;
  size_t cloud_points = 0;
  size_t mesh_triangles = 0;
  /// Filled when fusion ran.
  struct Fusion {
    size_t stable = 0, unstable = 0, memory_bytes = 0;
    int frames_fused = 0, frames_aligned_to_model = 0, frames_model_fallback = 0;
    int surfels_refused = 0;
    long merged = 0, confirmed = 0, added = 0, removed_unconfirmed = 0, removed_free_space = 0,
         merged_duplicates = 0;
    vicc_tracking::SampleSummary fusion_ms, model_prediction_ms, pipeline_ms;
  };
  std::optional<Fusion> fusion;
  std::optional<ModelAccuracy> accuracy;
  std::optional<vicc_tracking::TrajectoryError> ground_truth_error;
};

nlohmann::json makeReport(const ReconstructOptions& options, const ReconstructRun& run,
                          const vicc_tracking::TrackingStatistics& statistics);

}  // namespace vicc_fusion
