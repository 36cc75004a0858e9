#include "vicc_tracking/tracker_parameters.hpp"

#include <stdexcept>

namespace vicc_tracking {

void TrackerNodeSettings::validate() const {
  if (map_frame.empty()) throw std::invalid_argument("map_frame must not be empty");
  if (max_path_length < 1) throw std::invalid_argument("max_path_length must be >= 1");
  if (max_pending_frames < 0) throw std::invalid_argument("max_pending_frames must be >= 0");
}

}  // namespace vicc_tracking
