#pragma once
// dynamic_reconfigure of the surfel fusion's confidence and merge thresholds while it runs, on
// ~fusion (cfg/FusionTuning.cfg) under the keys of the fusion/ parameter section; the section's
// table converts between the two (vicc_tracking::toTuning, fromTuning), the fields the .cfg
// leaves out (supersampling, max_surfels, sort_interval) stay start-up parameters.

#include "vicc_fusion/FusionTuningConfig.h"
#include "vicc_fusion/fusion_parameters.hpp"
#include "vicc_fusion/surfel_fusion_config.hpp"
#include "vicc_tracking/ros/reconfigurable_section.hpp"

namespace vicc_fusion {

using FusionReconfigure =
    vicc_tracking::ReconfigurableSection<SurfelFusionConfig, FusionTuningConfig>;

}  // namespace vicc_fusion
