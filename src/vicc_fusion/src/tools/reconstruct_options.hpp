#pragma once
// Command line of vicc_reconstruct (the contract later issues extend).

#include <ostream>
#include <string>
#include <vector>

#include "vicc_fusion/frame_to_model.hpp"
#include "vicc_tracking/tracker.hpp"

namespace vicc_fusion {

struct ReconstructOptions {
  std::string bag_path;
  std::string depth_topic;  ///< empty: the only sensor_msgs/Image topic
  std::string info_topic;
  std::string imu_topic;
  /// The gray (amplitude) image fused as the surfels' intensity. Empty: the only mono8/mono16
  /// Image topic besides the depth, if there is exactly one; "none": no intensity.
  std::string intensity_topic;
  /// --config FILE.yaml, repeatable, applied in order: the tracker node's layout
  /// (config/tracker.yaml), the fusion node's (config/fusion.yaml) or both merged (the fusion
  /// node's namespace). --init, --levels, --frame-to-frame and --no-fusion override them.
  std::vector<std::string> config_paths;
  vicc_tracking::TrackerConfig tracker;
  FrameToModelConfig model;  ///< fusion/*, prediction/*, frame_to_model, min_prediction_coverage
  vicc_tracking::InitStrategyType init = vicc_tracking::InitStrategyType::kEkf;  ///< = tracker's
  int levels = 3;  ///< = tracker.preprocessing.pyramid_levels
  int frame_step = 1;
  std::string trajectory_path;
  std::string cloud_path;
  std::string mesh_path;       ///< optional surface mesh of the stable surfels
  bool frame_to_model = true;  ///< false: fuse, but track frame-to-frame (comparison)
  bool fusion = true;          ///< false: tracking only (no model, no cloud)
  std::string report_path;
  std::string ground_truth_path;
  std::string truth_surface_path;  ///< optional true surface PLY (vicc_make_bag --surface)  ///<
                                   ///< optional TUM file: adds the error against it to the report
  bool quiet = false;              ///< no progress line
};

/// Throws std::invalid_argument (vicc_common::cli::UsageError for the command line itself)
/// with a message for the user on bad arguments.
/// Returns false when --help was given (usage printed to `out`).
bool parseReconstructOptions(int argc, const char* const* argv, ReconstructOptions& options,
                             std::ostream& out);
void printReconstructUsage(std::ostream& out);

}  // namespace vicc_fusion
