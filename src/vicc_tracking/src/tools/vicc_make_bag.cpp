// vicc_make_bag SCENARIO --out FILE.bag [--gt FILE.tum] [--surface FILE.ply] [--start-time SEC]
// Writes the recording the simulated rig would produce (same code as the publisher nodes),
// as fast as the renderer allows.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

#include <rosbag/bag.h>
#include <tf2_msgs/TFMessage.h>
#include <boost/make_shared.hpp>

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

Options parseOptions(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::runtime_error(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "--out") {
      options.bag_path = value();
    } else if (arg == "--gt") {
      options.gt_path = value();
    } else if (arg == "--surface") {
      options.surface_path = value();
    } else if (arg == "--start-time") {
      const std::string text = value();
      char* end = nullptr;
      options.start_time = std::strtod(text.c_str(), &end);
      if (*end != '\0' || !(options.start_time > 0.0)) {
        throw std::runtime_error("--start-time must be a positive number of seconds");
      }
    } else if (arg == "-h" || arg == "--help") {
      printUsage(std::cout);
      std::exit(0);
    } else if (!arg.empty() && arg[0] == '-') {
      throw std::runtime_error("unknown option " + arg);
    } else if (options.scenario.empty()) {
      options.scenario = arg;
    } else {
      throw std::runtime_error("more than one scenario given: " + arg);
    }
  }
  if (options.scenario.empty()) throw std::runtime_error("no scenario given");
  if (options.bag_path.empty()) throw std::runtime_error("--out FILE.bag is required");
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
  Options options;
  try {
    options = parseOptions(argc, argv);
  } catch (const std::exception& error) {
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
