#include "reconstruct_options.hpp"

#include <algorithm>

#include "vicc_common/command_line.hpp"
#include "vicc_fusion/fusion_config_yaml.hpp"

namespace vicc_fusion {
namespace {

namespace cli = vicc_common::cli;

const std::vector<cli::OptionSpec> kOptionSpecs = {
    {"help", "", ""},        {"depth-topic", "T", ""},     {"info-topic", "T", ""},
    {"imu-topic", "T", ""},  {"intensity-topic", "T", ""}, {"init", "STRATEGY", ""},
    {"levels", "N", ""},     {"config", "FILE", "", true}, {"imu-noise", "FILE", ""},
    {"frame-step", "N", ""}, {"trajectory", "OUT", ""},    {"cloud", "OUT", ""},
    {"mesh", "OUT", ""},     {"frame-to-frame", "", ""},   {"no-fusion", "", ""},
    {"report", "OUT", ""},   {"gt", "TRUTH", ""},          {"truth-surface", "SURFACE", ""},
    {"quiet", "", ""},
};

/// The --config files in order, then the command line's overrides; the IMU noise file (from a
/// file or --imu-noise) is applied once, after everything that could set the EKF's noise.
void readParameters(const cli::ParsedArguments& parsed, ReconstructOptions& options) {
  FusionParameterSet parameters;
  options.config_paths = parsed.all("config");
  for (const std::string& path : options.config_paths) loadFusionParameters(path, parameters);
  options.tracker = parameters.tracker.tracker;
  options.model = parameters.model;
  if (parsed.has("init")) {
    options.tracker.init_strategy = vicc_tracking::initStrategyFromString(parsed.value("init"));
  }
  options.tracker.preprocessing.pyramid_levels =
      parsed.integer("levels", options.tracker.preprocessing.pyramid_levels, 1, 3);
  if (parsed.has("imu-noise")) options.tracker.ekf.imu_noise_file = parsed.value("imu-noise");
  vicc_tracking::applyImuNoiseFile(options.tracker);
  options.init = options.tracker.init_strategy;
  options.levels = options.tracker.preprocessing.pyramid_levels;
}

void checkCombinations(const ReconstructOptions& options) {
  if (!options.fusion && (!options.cloud_path.empty() || !options.mesh_path.empty() ||
                          !options.truth_surface_path.empty())) {
    throw cli::UsageError("--cloud, --mesh and --truth-surface need the model: drop --no-fusion");
  }
  if (!options.fusion && !options.intensity_topic.empty() && options.intensity_topic != "none") {
    throw cli::UsageError("--intensity-topic needs the model: drop --no-fusion");
  }
  if (!options.truth_surface_path.empty() && options.ground_truth_path.empty()) {
    throw cli::UsageError("--truth-surface needs --gt (to place the model in the truth's frame)");
  }
}

}  // namespace

void printReconstructUsage(std::ostream& out) {
  out << "usage: vicc_reconstruct BAG [--depth-topic T] [--info-topic T] [--imu-topic T]\n"
         "                        [--intensity-topic T|none]\n"
         "                        [--init ekf|identity|constant_velocity|imu] [--levels 1|2|3]\n"
         "                        [--frame-step N] [--trajectory OUT.tum] [--cloud OUT.ply]\n"
         "                        [--mesh OUT.ply] [--report OUT.json] [--gt TRUTH.tum]\n"
         "                        [--truth-surface SURFACE.ply] [--frame-to-frame | --no-fusion]\n"
         "                        [--config PARAMS.yaml ...] [--imu-noise IMU.yaml] [--quiet]\n"
         "Tracks the depth camera through a depth + IMU recording (thesis 5.4) and fuses the\n"
         "frames into a surfel model it tracks against (frame-to-model, thesis 2.2.2, 5.3).\n"
         "  topics       default to the only Image / CameraInfo / Imu topic in the bag\n"
         "  --intensity-topic  gray (amplitude) image fused as the surfels' intensity, matched\n"
         "               to the depth by header stamp; default: the only mono8/mono16 Image\n"
         "               topic besides the depth if there is exactly one; none: no intensity\n"
         "  --init       ICP initial guess: ekf (default, the thesis), identity (KinectFusion),\n"
         "               constant_velocity, imu (plain IMU integration); overrides --config\n"
         "  --levels     image pyramid levels for ICP (default 3); overrides --config\n"
         "  --config     parameters in the nodes' layout, repeatable, applied in order: the\n"
         "               tracker's (vicc_tracking config/tracker.yaml: init_strategy,\n"
         "               preprocessing, icp, ekf, still_phase, imu_sync) and the fusion's\n"
         "               (vicc_fusion config/fusion.yaml: frame_to_model,\n"
         "               min_prediction_coverage, fusion, prediction); keys left out keep their\n"
         "               defaults, unknown keys and wrong types are errors, the node-only keys\n"
         "               (map_frame, publish_tf, track, publish_rate, ...) are accepted, unused\n"
         "  --imu-noise  the IMU's noise figures in Kalibr's imu.yaml layout (noise densities,\n"
         "               random walks, update_rate): the EKF's process noise is derived from\n"
         "               them (vicc_tracking docs/imu_noise.md); overrides ekf/imu_noise_file\n"
         "  --frame-step process every N-th depth frame (thesis: All = 1, 1/2 = 2, 1/4 = 4)\n"
         "  --trajectory camera optical frame in map, TUM format, one line per tracked frame\n"
         "  --cloud      the stable surfels in map: binary PLY with normals, radius, confidence\n"
         "  --mesh       a surface mesh of the stable surfels (PCL greedy projection), PLY\n"
         "  --frame-to-frame  fuse, but align each frame to the previous one (comparison)\n"
         "  --no-fusion  tracking only, frame-to-frame (no model; --cloud/--mesh not allowed)\n"
         "  --report     JSON: frames processed/lost, ICP iterations, Init_EKF/Init_Id, timings,\n"
         "               surfel counts, fusion ms per frame, model memory, the tracker's\n"
         "               parameters\n"
         "  --gt         ground-truth TUM trajectory (e.g. from vicc_make_bag --gt): the report\n"
         "               adds the pose error, both aligned at the first tracked frame\n"
         "  --truth-surface  the true surface (vicc_make_bag --surface; needs --gt): the report\n"
         "               adds the stable surfels' distance to it and its completeness\n"
         "  --quiet      no progress line\n";
}

bool parseReconstructOptions(int argc, const char* const* argv, ReconstructOptions& options,
                             std::ostream& out) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (std::find(args.begin(), args.end(), "-h") != args.end()) {
    printReconstructUsage(out);
    return false;
  }
  const cli::ParsedArguments parsed = cli::parseArguments(args, kOptionSpecs);
  if (parsed.flag("help")) {
    printReconstructUsage(out);
    return false;
  }
  if (parsed.positional.empty()) throw cli::UsageError("no bag given");
  if (parsed.positional.size() > 1) {
    throw cli::UsageError("more than one bag given: " + parsed.positional[1]);
  }
  options.bag_path = parsed.positional.front();
  options.depth_topic = parsed.value("depth-topic");
  options.info_topic = parsed.value("info-topic");
  options.imu_topic = parsed.value("imu-topic");
  options.intensity_topic = parsed.value("intensity-topic");
  if (parsed.has("intensity-topic") && options.intensity_topic.empty()) {
    throw cli::UsageError("--intensity-topic needs a topic or 'none'");
  }
  options.frame_step = parsed.integer("frame-step", options.frame_step, 1, 1000000);
  options.trajectory_path = parsed.value("trajectory");
  options.cloud_path = parsed.value("cloud");
  options.mesh_path = parsed.value("mesh");
  options.report_path = parsed.value("report");
  options.ground_truth_path = parsed.value("gt");
  options.truth_surface_path = parsed.value("truth-surface");
  options.quiet = parsed.flag("quiet");
  readParameters(parsed, options);
  options.fusion = !parsed.flag("no-fusion");
  if (parsed.flag("frame-to-frame") || !options.fusion) options.model.track_against_model = false;
  options.frame_to_model = options.model.track_against_model;
  checkCombinations(options);
  return true;
}

}  // namespace vicc_fusion
