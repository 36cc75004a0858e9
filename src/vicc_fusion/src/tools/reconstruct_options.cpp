#include "reconstruct_options.hpp"

#include <cstdlib>
#include <optional>
#include <stdexcept>

#include "vicc_tracking/tracker_config_yaml.hpp"

namespace vicc_fusion {
namespace {

int parsePositiveInt(const std::string& option, const std::string& text) {
  char* end = nullptr;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || value < 1 || value > 1000000) {
    throw std::invalid_argument(option + " needs a positive integer, got '" + text + "'");
  }
  return static_cast<int>(value);
}

}  // namespace

void printReconstructUsage(std::ostream& out) {
  out << "usage: vicc_reconstruct BAG [--depth-topic T] [--info-topic T] [--imu-topic T]\n"
         "                        [--intensity-topic T|none]\n"
         "                        [--init ekf|identity|constant_velocity|imu] [--levels 1|2|3]\n"
         "                        [--frame-step N] [--trajectory OUT.tum] [--cloud OUT.ply]\n"
         "                        [--mesh OUT.ply] [--report OUT.json] [--gt TRUTH.tum]\n"
         "                        [--truth-surface SURFACE.ply] [--frame-to-frame | --no-fusion]\n"
         "                        [--config TRACKER.yaml] [--imu-noise IMU.yaml] [--quiet]\n"
         "Tracks the depth camera through a depth + IMU recording (thesis 5.4) and fuses the\n"
         "frames into a surfel model it tracks against (frame-to-model, thesis 2.2.2, 5.3).\n"
         "  topics       default to the only Image / CameraInfo / Imu topic in the bag\n"
         "  --intensity-topic  gray (amplitude) image fused as the surfels' intensity, matched\n"
         "               to the depth by header stamp; default: the only mono8/mono16 Image\n"
         "               topic besides the depth if there is exactly one; none: no intensity\n"
         "  --init       ICP initial guess: ekf (default, the thesis), identity (KinectFusion),\n"
         "               constant_velocity, imu (plain IMU integration); overrides --config\n"
         "  --levels     image pyramid levels for ICP (default 3); overrides --config\n"
         "  --config     tracker parameters in the tracker node's layout (config/tracker.yaml:\n"
         "               init_strategy, preprocessing, icp, ekf, still_phase, imu_sync); keys\n"
         "               left out keep their defaults, unknown keys and wrong types are errors,\n"
         "               the node-only keys (map_frame, publish_tf, ...) are accepted, unused\n"
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
  std::optional<vicc_tracking::InitStrategyType> init;
  std::optional<int> levels;
  std::optional<std::string> imu_noise;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "-h" || arg == "--help") {
      printReconstructUsage(out);
      return false;
    } else if (arg == "--depth-topic") {
      options.depth_topic = value();
    } else if (arg == "--info-topic") {
      options.info_topic = value();
    } else if (arg == "--imu-topic") {
      options.imu_topic = value();
    } else if (arg == "--intensity-topic") {
      options.intensity_topic = value();
      if (options.intensity_topic.empty()) {
        throw std::invalid_argument("--intensity-topic needs a topic or 'none'");
      }
    } else if (arg == "--init") {
      init = vicc_tracking::initStrategyFromString(value());
    } else if (arg == "--levels") {
      levels = parsePositiveInt(arg, value());
      if (*levels > 3) throw std::invalid_argument("--levels must be 1, 2 or 3");
    } else if (arg == "--config") {
      options.config_path = value();
    } else if (arg == "--imu-noise") {
      imu_noise = value();
    } else if (arg == "--frame-step") {
      options.frame_step = parsePositiveInt(arg, value());
    } else if (arg == "--trajectory") {
      options.trajectory_path = value();
    } else if (arg == "--cloud") {
      options.cloud_path = value();
    } else if (arg == "--mesh") {
      options.mesh_path = value();
    } else if (arg == "--frame-to-frame") {
      options.frame_to_model = false;
    } else if (arg == "--no-fusion") {
      options.fusion = false;
      options.frame_to_model = false;
    } else if (arg == "--report") {
      options.report_path = value();
    } else if (arg == "--gt") {
      options.ground_truth_path = value();
    } else if (arg == "--truth-surface") {
      options.truth_surface_path = value();
    } else if (arg == "--quiet") {
      options.quiet = true;
    } else if (!arg.empty() && arg[0] == '-') {
      throw std::invalid_argument("unknown option " + arg);
    } else if (options.bag_path.empty()) {
      options.bag_path = arg;
    } else {
      throw std::invalid_argument("more than one bag given: " + arg);
    }
  }
  if (options.bag_path.empty()) throw std::invalid_argument("no bag given");
  options.tracker = options.config_path.empty()
                        ? vicc_tracking::TrackerConfig{}
                        : vicc_tracking::loadTrackerParameters(options.config_path).tracker;
  if (init) options.tracker.init_strategy = *init;
  if (levels) options.tracker.preprocessing.pyramid_levels = *levels;
  if (imu_noise) {
    options.tracker.ekf.imu_noise_file = *imu_noise;
    vicc_tracking::applyImuNoiseFile(options.tracker);
  }
  options.init = options.tracker.init_strategy;
  options.levels = options.tracker.preprocessing.pyramid_levels;
  if (!options.fusion && (!options.cloud_path.empty() || !options.mesh_path.empty() ||
                          !options.truth_surface_path.empty())) {
    throw std::invalid_argument(
        "--cloud, --mesh and --truth-surface need the model: drop --no-fusion");
  }
  if (!options.fusion && !options.intensity_topic.empty() && options.intensity_topic != "none") {
    throw std::invalid_argument("--intensity-topic needs the model: drop --no-fusion");
  }
  if (!options.truth_surface_path.empty() && options.ground_truth_path.empty()) {
    throw std::invalid_argument(
        "--truth-surface needs --gt (to place the model in the truth's frame)");
  }
  return true;
}

}  // namespace vicc_fusion
