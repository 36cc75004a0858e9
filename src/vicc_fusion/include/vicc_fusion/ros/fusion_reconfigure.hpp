#pragma once
// dynamic_reconfigure of the surfel fusion's confidence and merge thresholds while it runs, on
// ~fusion (cfg/FusionTuning.cfg) under the keys of the fusion/ parameter section.

#include "vicc_fusion/FusionTuningConfig.h"
#include "vicc_fusion/surfel_fusion_config.hpp"
#include "vicc_tracking/ros/reconfigurable_section.hpp"

namespace vicc_fusion {

/// The .cfg's fields from the config and back; the fields it does not cover keep `base`'s.
FusionTuningConfig toTuning(const SurfelFusionConfig& fusion);
SurfelFusionConfig fromTuning(const FusionTuningConfig& tuning, SurfelFusionConfig base);

using FusionReconfigure =
    vicc_tracking::ReconfigurableSection<SurfelFusionConfig, FusionTuningConfig>;

}  // namespace vicc_fusion
