#pragma once
// vicc_msgs/EncodedStatus -> the core's EncodedStatus, which the avatar view logic reads.

#include <string>
#include <vector>

#include <vicc_msgs/EncodedStatus.h>

#include "vicc_anatomy_viz/status_encoder.hpp"

namespace vicc_anatomy_viz::rviz_plugin {

/// Field by field; a side or time the core cannot read is reported in `warnings` (the entry
/// then names side "none", which the avatar does not have for bilateral structures, so it is
/// left out and warned about again instead of being drawn on a guessed side).
EncodedStatus fromMessage(const vicc_msgs::EncodedStatus& msg, std::vector<std::string>& warnings);

}  // namespace vicc_anatomy_viz::rviz_plugin
