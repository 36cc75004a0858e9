// vicc_make_bag SCENARIO --out FILE.bag [--gt FILE.tum] [--surface FILE.ply] [--start-time SEC]
// Writes the recording the simulated rig would produce (same code as the publisher nodes),
// as fast as the renderer allows.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <rosbag/bag.h>
#include <tf2_msgs/TFMessage.h>
#include <boost/make_shared.hpp>

#include "vicc_common/command_line.hpp"
#include "vicc_tracking/ros/rig_messages.hpp"
#include "vicc_tracking/sim/visible_surface.hpp"
#include "vicc_tracking/tum_trajectory.hpp"

namespace {

void printUsage(std::ostream& out) {
  out << "usage: vicc_make_bag SCENARIO --out FILE.bag [--gt FILE.tum] [--surface FILE.ply]\n"
         "                     [--start-time SEC]\n"
         "  SCENARIO: a name (";
  const auto names = vicc_tracking::sim::availableScenarios();
  for (size_t i = 0; i < names.size(); ++i) out << (i ? ", " : "") << names[i];
  out << ") or a scenario YAML file\n"
         "  --gt FILE.tum     ground truth camera poses (optical frame in map) at the depth "
         "stamps\n"
         "  --surface FILE.ply the true surface the recording saw (2 mm samples with normals,\n"
         "                    map frame): the reference for reconstruction accuracy\n"
         "  --start-time SEC  stamp of the first message (default 1700000000)\n";
}

struct Options {
  std::string scenario;
  std::string bag_path;
  std::string gt_path;
  std::string surface_path;
  double start_time = 1700000000.0;
};

namespace cli = vicc_common::cli;

const std::vector<cli::OptionSpec> kOptionSpecs = {
    {"out", "FILE.bag", ""},   {"gt", "FILE.tum", ""}, {"surface", "FILE.ply", ""},
    {"start-time", "SEC", ""}, {"help", "", ""},
};

/// Throws cli::UsageError; std::nullopt for --help.
std::optional<Options> parseOptions(const std::vector<std::string>& args) {
  const cli::ParsedArguments parsed = cli::parseArguments(args, kOptionSpecs);
  if (parsed.flag("help")) return std::nullopt;
  if (parsed.positional.empty()) throw cli::UsageError("no scenario given");
  if (parsed.positional.size() > 1) {
    throw cli::UsageError("more than one scenario given: " + parsed.positional[1]);
  }
  Options options;
  options.scenario = parsed.positional.front();
  options.bag_path = parsed.value("out");
  if (options.bag_path.empty()) throw cli::UsageError("--out FILE.bag is required");
  options.gt_path = parsed.value("gt");
  options.surface_path = parsed.value("surface");
  // Any time ros::Time can hold (unsigned 32-bit seconds), from the first second on.
  options.start_time = parsed.number("start-time", options.start_time, 1.0, 4294967295.0);
  return options;
}

/// /tf_static must be latched on playback; rosbag keeps the flag from the connection header.
boost::shared_ptr<ros::M_string> latchedHeader() {
  using tf2_msgs::TFMessage;
  auto header = boost::make_shared<ros::M_string>();
  // A custom connection header replaces rosbag's, so it must carry the type fields too.
  (*header)["type"] = ros::message_traits::datatype<TFMessage>();
  (*header)["md5sum"] = ros::message_traits::md5sum<TFMessage>();
  (*header)["message_definition"] = ros::message_traits::definition<TFMessage>();
  (*header)["latching"] = "1";
  (*header)["callerid"] = "/imu_publisher";
  return header;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  std::replace(args.begin(), args.end(), std::string("-h"), std::string("--help"));
  Options options;
  try {
    const std::optional<Options> parsed = parseOptions(args);
    if (!parsed) {
      printUsage(std::cout);
      return 0;
    }
    options = *parsed;
  } catch (const cli::UsageError& error) {
    std::cerr << "vicc_make_bag: " << error.what() << "\n";
    printUsage(std::cerr);
    return 2;
  }
  try {
    using vicc_tracking::RigTopics;
    const vicc_tracking::sim::RigSimulator rig(vicc_tracking::sim::loadScenario(options.scenario));
    const ros::Time t0(options.start_time);
    const std::vector<double> depth_times = rig.depthTimes();
    const std::vector<double> imu_times = rig.imuTimes();

    rosbag::Bag bag(options.bag_path, rosbag::bagmode::Write);
    tf2_msgs::TFMessage extrinsic;
    extrinsic.transforms.push_back(vicc_tracking::rigExtrinsic(rig, t0));
    bag.write("/tf_static", t0, extrinsic, latchedHeader());

    std::vector<vicc_tracking::TimedPose> ground_truth_poses;
    // Merge both sensors in time order, IMU first on equal stamps (it is what the driver
    // delivers with lower latency).
    size_t next_imu = 0;
    for (size_t k = 0; k < depth_times.size(); ++k) {
      while (next_imu < imu_times.size() && imu_times[next_imu] <= depth_times[k]) {
        const ros::Time stamp = t0 + ros::Duration(imu_times[next_imu]);
        bag.write(RigTopics::kImu, stamp,
                  vicc_tracking::rigImuMessage(rig, static_cast<int>(next_imu), stamp));
        ++next_imu;
      }
      const ros::Time stamp = t0 + ros::Duration(depth_times[k]);
      bag.write(RigTopics::kCameraInfo, stamp, vicc_tracking::rigCameraInfo(rig, stamp));
      const vicc_tracking::RigImages images =
          vicc_tracking::rigImageMessages(rig, static_cast<int>(k), stamp);
      bag.write(RigTopics::kDepth, stamp, images.depth);
      bag.write(RigTopics::kGray, stamp, images.gray);
      tf2_msgs::TFMessage ground_truth;
      ground_truth.transforms.push_back(vicc_tracking::rigGroundTruth(rig, depth_times[k], stamp));
      bag.write("/tf", stamp, ground_truth);
      ground_truth_poses.push_back({stamp.toSec(), rig.cameraPose(depth_times[k])});
      if (k % 50 == 0 || k + 1 == depth_times.size()) {
        std::fprintf(stderr, "\rvicc_make_bag: %zu/%zu depth frames", k + 1, depth_times.size());
      }
    }
    for (; next_imu < imu_times.size(); ++next_imu) {
      const ros::Time stamp = t0 + ros::Duration(imu_times[next_imu]);
      bag.write(RigTopics::kImu, stamp,
                vicc_tracking::rigImuMessage(rig, static_cast<int>(next_imu), stamp));
    }
    bag.close();
    if (!options.gt_path.empty()) {
      vicc_tracking::writeTumTrajectory(options.gt_path, ground_truth_poses);
    }
    if (!options.surface_path.empty()) {
      std::fprintf(stderr, "\n");
      const auto surface = vicc_tracking::sim::visibleSurface(
          rig, vicc_tracking::sim::VisibleSurfaceConfig{}, [](size_t done, size_t total) {
            std::fprintf(stderr, "\rvicc_make_bag: visible surface, frame %zu/%zu", done, total);
          });
      vicc_tracking::sim::writeSurfacePly(options.surface_path, surface);
      std::fprintf(stderr, "\nvicc_make_bag: wrote %s (%zu true surface points)",
                   options.surface_path.c_str(), surface.size());
    }
    std::fprintf(stderr, "\nvicc_make_bag: wrote %s (%.1f s, %zu depth frames, %zu IMU readings)\n",
                 options.bag_path.c_str(), rig.duration(), depth_times.size(), imu_times.size());
  } catch (const std::exception& error) {
    std::cerr << "vicc_make_bag: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
