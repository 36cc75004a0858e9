#pragma once
// The fusion node's parameter tables, ROS-free (the style of
// vicc_tracking/tracker_parameters.hpp): one (key, field) table per config struct, walked by
// vicc_common's YAML reader/writer and ROS reader. Keys follow config/fusion.yaml.

#include <string>
#include <type_traits>

#include "vicc_fusion/frame_to_model.hpp"

namespace vicc_fusion {

/// Settings only the fusion node uses (mode, frames, publishing). Plain data, kept in the core
/// so that vicc_reconstruct accepts the node's parameter file as it is.
struct FusionRosSettings {
  bool track = true;
  std::string map_frame = "map";  ///< track: false only; with track: true the tracker's
  double publish_rate = 1.0;      ///< Hz of ~model; 0 = never
  /// track: false: depth frames held until the external tracker's pose for their stamp is on
  /// tf (tf2_ros::MessageFilter, never blocking the callbacks); the oldest go first.
  int pose_queue_size = 10;
  /// Fuse the gray image of `intensity/image` (mono8/mono16/32FC1, the sensor's grid) as surfel
  /// intensity: each depth frame takes the gray image with its exact stamp, if it arrived.
  bool use_intensity = false;
  void validate() const;
};

template <typename Config, typename Type>
using EnableForConfig = std::enable_if_t<std::is_same_v<std::remove_const_t<Config>, Type>>;

template <typename Config, typename Visitor>
EnableForConfig<Config, SurfelFusionConfig> visitParameters(Config& config, Visitor& visit) {
  visit("supersampling", config.supersampling);
  visit("max_depth_difference", config.max_depth_difference);
  visit("max_normal_angle_deg", config.max_normal_angle_deg);
  visit("max_radius_growth", config.max_radius_growth);
  visit("confidence_sigma", config.confidence_sigma);
  visit("stable_confidence", config.stable_confidence);
  visit("unstable_lifetime", config.unstable_lifetime);
  visit("free_space_margin", config.free_space_margin);
  visit("max_view_distance", config.max_view_distance);
  visit("max_surfels", config.max_surfels);
  visit("sort_interval", config.sort_interval);
}

/// stable_confidence is not a key here: the prediction draws the surfels fusion/ calls stable.
template <typename Config, typename Visitor>
EnableForConfig<Config, ModelPredictionConfig> visitParameters(Config& config, Visitor& visit) {
  visit("splat_radius_scale", config.splat_radius_scale);
  visit("blend_depth", config.blend_depth);
  visit("max_splat_radius_px", config.max_splat_radius_px);
  visit("min_depth", config.min_depth);
}

template <typename Config, typename Visitor>
EnableForConfig<Config, FrameToModelConfig> visitParameters(Config& config, Visitor& visit) {
  visit("frame_to_model", config.track_against_model);
  visit("min_prediction_coverage", config.min_prediction_coverage);
  visit.section("fusion", config.fusion);
  visit.section("prediction", config.prediction);
}

template <typename Config, typename Visitor>
EnableForConfig<Config, FusionRosSettings> visitParameters(Config& config, Visitor& visit) {
  visit("track", config.track);
  visit("map_frame", config.map_frame);
  visit("publish_rate", config.publish_rate);
  visit("pose_queue_size", config.pose_queue_size);
  visit("use_intensity", config.use_intensity);
}

}  // namespace vicc_fusion
