#pragma once
// JSON form of an encoded status (the same content as vicc_msgs/EncodedStatus), for the CLI,
// the services and any consumer without ROS.

#include <nlohmann/json.hpp>

#include "vicc_anatomy_viz/status_encoder.hpp"

namespace vicc_anatomy_viz {

nlohmann::json toJson(const EncodedStatus& status);

}  // namespace vicc_anatomy_viz
