#pragma once
#include <vicc_msgs/TrackingStatus.h>

#include "vicc_tracking/init_strategy.hpp"
#include "vicc_tracking/tracker.hpp"

namespace vicc_tracking {

vicc_msgs::TrackingStatus statusMessage(const FrameReport& report, InitStrategyType strategy);

}  // namespace vicc_tracking
