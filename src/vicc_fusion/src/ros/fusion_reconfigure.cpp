#include "vicc_fusion/ros/fusion_reconfigure.hpp"

namespace vicc_fusion {

FusionTuningConfig toTuning(const SurfelFusionConfig& fusion) {
  FusionTuningConfig tuning = FusionTuningConfig::__getDefault__();
  tuning.max_depth_difference = fusion.max_depth_difference;
  tuning.max_normal_angle_deg = fusion.max_normal_angle_deg;
  tuning.max_radius_growth = fusion.max_radius_growth;
  tuning.confidence_sigma = fusion.confidence_sigma;
  tuning.stable_confidence = fusion.stable_confidence;
  tuning.unstable_lifetime = fusion.unstable_lifetime;
  tuning.free_space_margin = fusion.free_space_margin;
  tuning.max_view_distance = fusion.max_view_distance;
  return tuning;
}

SurfelFusionConfig fromTuning(const FusionTuningConfig& tuning, SurfelFusionConfig base) {
  base.max_depth_difference = tuning.max_depth_difference;
  base.max_normal_angle_deg = tuning.max_normal_angle_deg;
  base.max_radius_growth = tuning.max_radius_growth;
  base.confidence_sigma = tuning.confidence_sigma;
  base.stable_confidence = tuning.stable_confidence;
  base.unstable_lifetime = tuning.unstable_lifetime;
  base.free_space_margin = tuning.free_space_margin;
  base.max_view_distance = tuning.max_view_distance;
  return base;
}

}  // namespace vicc_fusion
