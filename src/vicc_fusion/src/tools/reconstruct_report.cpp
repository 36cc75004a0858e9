#include "reconstruct_report.hpp"

#include "vicc_common/json_parameters.hpp"
#include "vicc_fusion/fusion_parameters.hpp"
#include "vicc_tracking/tracker_parameters.hpp"

namespace vicc_fusion {
namespace {

nlohmann::json meanStd(const vicc_tracking::SampleSummary& summary) {
  return {{"mean", summary.mean}, {"std", summary.stddev}, {"count", summary.count}};
}

}  // namespace

nlohmann::json makeReport(const ReconstructOptions& options, const ReconstructRun& run,
                          const vicc_tracking::TrackingStatistics& statistics) {
  nlohmann::json report;
  report["bag"] = options.bag_path;
  report["topics"] = {
      {"depth", run.depth_topic}, {"camera_info", run.info_topic}, {"imu", run.imu_topic}};
  report["intensity"] = {
      {"topic",
       run.intensity_topic.empty() ? nlohmann::json(nullptr) : nlohmann::json(run.intensity_topic)},
      {"frames_with_intensity", run.frames_with_intensity},
      {"frames_without_intensity", run.frames_without_intensity},
      {"stable_surfels_with_intensity", run.stable_with_intensity}};
  report["settings"] = {{"init", vicc_tracking::toString(options.init)},
                        {"levels", options.levels},
                        {"frame_step", options.frame_step}};
  report["frames"] = {{"in_bag", run.depth_frames_in_bag},
                      {"skipped_by_frame_step", run.depth_frames_skipped},
                      {"processed", statistics.framesSeen() - statistics.framesDropped()},
                      {"dropped_invalid", statistics.framesDropped()},
                      {"initializing", statistics.framesInitializing()},
                      {"tracked", statistics.framesTracked()},
                      {"lost", statistics.framesLost()}};
  report["icp_iterations"] = meanStd(statistics.iterations());
  report["init_ratio"] = {{"what",
                           "|initial guess - ICP pose| / |previous pose - ICP pose| "
                           "(Init_EKF / Init_Id in thesis 5.5.1)"},
                          {"position", meanStd(statistics.initRatioPosition())},
                          {"rotation", meanStd(statistics.initRatioRotation())}};
  report["median_ms"] = {{"preprocessing", statistics.preprocessingMs().median},
                         {"prediction", statistics.predictionMs().median},
                         {"icp", statistics.icpMs().median},
                         {"tracking_total", statistics.totalMs().median}};
  if (const auto drift = statistics.loopClosureDrift()) {
    report["first_to_last_pose"] = {
        {"what", "difference between first and last tracked pose; drift on a closed loop"},
        {"position_m", drift->translation},
        {"rotation_deg", drift->rotation_deg}};
  }
  const int processed = statistics.framesSeen() - statistics.framesDropped();
  report["wall_time_s"] = run.wall_time_s;
  report["frames_per_second"] = run.wall_time_s > 0 ? processed / run.wall_time_s : 0.0;
  if (!options.cloud_path.empty()) report["cloud_points"] = run.cloud_points;
  if (!options.mesh_path.empty()) report["mesh_triangles"] = run.mesh_triangles;
  report["settings"]["fusion"] = options.fusion;
  std::string config_files;  // one string as before a second --config was possible
  for (const std::string& path : options.config_paths) {
    config_files += (config_files.empty() ? "" : ", ") + path;
  }
  report["settings"]["config"] = config_files;
  report["settings"]["config_files"] = options.config_paths;
  vicc_common::writeJsonParameters(options.tracker, report["tracker_parameters"]);
  if (options.fusion) vicc_common::writeJsonParameters(options.model, report["fusion_parameters"]);
  report["settings"]["tracking"] = options.frame_to_model ? "frame_to_model" : "frame_to_frame";
  if (run.fusion) {
    const ReconstructRun::Fusion& fusion = *run.fusion;
    const double pipeline_ms = fusion.pipeline_ms.median;
    auto perFrame = [&fusion](long total) {
      return fusion.frames_fused > 0 ? static_cast<double>(total) / fusion.frames_fused : 0.0;
    };
    report["surfels"] = {{"stable", fusion.stable},
                         {"unstable", fusion.unstable},
                         {"memory_bytes", fusion.memory_bytes},
                         {"refused_at_max_surfels", fusion.surfels_refused}};
    report["fusion"] = {
        {"frames_fused", fusion.frames_fused},
        {"frames_aligned_to_model", fusion.frames_aligned_to_model},
        {"frames_model_fallback", fusion.frames_model_fallback},
        {"per_frame_mean",
         {{"merged", perFrame(fusion.merged)},
          {"confirmed", perFrame(fusion.confirmed)},
          {"added", perFrame(fusion.added)},
          {"removed_unconfirmed", perFrame(fusion.removed_unconfirmed)},
          {"removed_free_space", perFrame(fusion.removed_free_space)},
          {"merged_duplicates", perFrame(fusion.merged_duplicates)}}},
        {"median_fusion_ms", fusion.fusion_ms.median},
        {"median_model_prediction_ms", fusion.model_prediction_ms.median},
        {"median_pipeline_ms", pipeline_ms},
        {"pipeline_frames_per_second", pipeline_ms > 0 ? 1000.0 / pipeline_ms : 0.0},
        {"what",
         "pipeline = preprocessing + prediction (EKF) + ICP + fusion + "
         "model prediction, per fused frame, one core"}};
  }
  if (run.accuracy) {
    const ModelAccuracy& accuracy = *run.accuracy;
    report["model_accuracy"] = {
        {"what",
         "stable surfels vs the true visible surface (point-to-plane), and the share of "
         "that surface within completeness_radius_m of a surfel"},
        {"surfels", accuracy.surfels},
        {"surfels_outside_reference", accuracy.surfels_outside},
        {"truth_points", accuracy.truth_points},
        {"mean_distance_m", accuracy.mean_distance},
        {"median_distance_m", accuracy.median_distance},
        {"p95_distance_m", accuracy.p95_distance},
        {"completeness", accuracy.completeness},
        {"completeness_radius_m", accuracy.completeness_radius}};
  }
  if (run.ground_truth_error) {
    const vicc_tracking::TrajectoryError& error = *run.ground_truth_error;
    report["ground_truth_error"] = {
        {"what", "tracked camera poses vs ground truth, aligned at the first tracked frame"},
        {"matched_poses", error.matched},
        {"rmse_position_m", error.rmse_position},
        {"max_position_m", error.max_position},
        {"max_rotation_deg", error.max_rotation_deg},
        {"final_position_m", error.final_position},
        {"final_rotation_deg", error.final_rotation_deg}};
  }
  return report;
}

}  // namespace vicc_fusion
