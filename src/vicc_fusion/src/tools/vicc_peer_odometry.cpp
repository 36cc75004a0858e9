// vicc_peer_odometry BAG [--frame-step N] [--levels 1|2|3] [--gt TRUTH.tum] [--report OUT.json]
// The benchmark's peer: OpenCV's cv::rgbd::ICPOdometry (KinectFusion-style point-to-plane ICP)
// with identity initialisation, on the same frames vicc_reconstruct sees, undistorted the same
// way. Reports failures and drift in vicc_reconstruct's JSON layout.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>
#include <opencv2/core/eigen.hpp>  // after Eigen, as OpenCV requires
#include <opencv2/rgbd.hpp>

#include "vicc_common/command_line.hpp"
#include "vicc_tracking/depth_preprocessing.hpp"
#include "vicc_tracking/ros/conversions.hpp"
#include "vicc_tracking/ros/rig_bag.hpp"
#include "vicc_tracking/tracking_statistics.hpp"
#include "vicc_tracking/trajectory_error.hpp"

namespace {

struct Options {
  std::string bag;
  int frame_step = 1;
  int levels = 3;
  std::string ground_truth;
  std::string report;
};

namespace cli = vicc_common::cli;

/// Throws cli::UsageError naming the option.
Options parse(int argc, char** argv) {
  const cli::ParsedArguments parsed = cli::parseArguments(
      std::vector<std::string>(argv + 1, argv + argc), {{"frame-step", "N", ""},
                                                        {"levels", "N", ""},
                                                        {"gt", "TRUTH.tum", ""},
                                                        {"report", "OUT.json", ""}});
  if (parsed.positional.size() != 1) throw cli::UsageError("give exactly one bag");
  Options options;
  options.bag = parsed.positional.front();
  options.frame_step = parsed.integer("frame-step", options.frame_step, 1, 1000000);
  options.levels = parsed.integer("levels", options.levels, 1, 3);
  options.ground_truth = parsed.value("gt");
  options.report = parsed.value("report");
  return options;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  try {
    options = parse(argc, argv);
  } catch (const std::exception& error) {
    std::cerr << "vicc_peer_odometry: " << error.what()
              << "\nusage: vicc_peer_odometry BAG [--frame-step N] [--levels 1|2|3] "
                 "[--gt TRUTH.tum] [--report OUT.json]\n";
    return 2;
  }
  try {
    cv::setNumThreads(1);  // one core, like the tracker's figures
    const vicc_tracking::RigBag bag(options.bag, {});
    vicc_tracking::PreprocessingConfig config;
    config.pyramid_levels = 1;
    vicc_tracking::DepthPreprocessor preprocessor(config);
    const std::vector<int> all_iterations{10, 5, 4};  // ours, finest level first
    const std::vector<int> iterations(all_iterations.begin(),
                                      all_iterations.begin() + options.levels);
    cv::Ptr<cv::rgbd::ICPOdometry> odometry;
    cv::Mat previous_depth;
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    std::vector<vicc_tracking::TimedPose> trajectory;
    std::vector<double> milliseconds;
    int failures = 0, processed = 0;
    size_t index = 0;
    bag.forEachDepthFrame(
        [&](const sensor_msgs::ImageConstPtr& image, const sensor_msgs::CameraInfoConstPtr& info) {
          if (index++ % options.frame_step != 0 || !info) return;
          if (!odometry) {
            preprocessor.setCamera(vicc_tracking::cameraModelFromInfo(*info));
            cv::Mat k(preprocessor.camera().intrinsicMatrix());
            cv::Mat k_float;
            k.convertTo(k_float, CV_32F);
            odometry = cv::rgbd::ICPOdometry::create(k_float, 0.1f, 4.0f, 0.07f, 1.0f, iterations);
          }
          const cv::Mat1f depth = preprocessor.undistort(
              vicc_tracking::toMetricDepth(vicc_tracking::depthImageView(*image)));
          const double stamp = image->header.stamp.toSec();
          ++processed;
          if (!previous_depth.empty()) {
            const auto start = std::chrono::steady_clock::now();
            cv::Mat rt;
            const bool ok = odometry->compute(cv::Mat(), depth, cv::Mat(), cv::Mat(),
                                              previous_depth, cv::Mat(), rt);
            milliseconds.push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count());
            if (ok) {
              Eigen::Matrix4d motion;
              cv::cv2eigen(rt, motion);
              Eigen::Isometry3d step(motion);
              pose = pose * step;  // rt maps the new frame's points into the previous frame
            } else {
              ++failures;
            }
          }
          trajectory.push_back({stamp, pose});
          previous_depth = depth;
        });
    nlohmann::json report;
    report["peer"] = "cv::rgbd::ICPOdometry, identity initialisation";
    report["settings"] = {{"frame_step", options.frame_step}, {"levels", options.levels}};
    report["frames"] = {{"processed", processed}, {"lost", failures}};
    if (trajectory.size() >= 2) {
      const auto drift =
          vicc_tracking::poseDifference(trajectory.front().pose, trajectory.back().pose);
      report["first_to_last_pose"] = {{"position_m", drift.translation},
                                      {"rotation_deg", drift.rotation_deg}};
    }
    report["median_ms"] = {{"odometry", vicc_tracking::summarize(milliseconds).median}};
    if (!options.ground_truth.empty()) {
      const auto error = vicc_tracking::compareTrajectories(
          trajectory, vicc_tracking::readTumTrajectory(options.ground_truth));
      report["ground_truth_error"] = {{"matched_poses", error.matched},
                                      {"rmse_position_m", error.rmse_position},
                                      {"max_position_m", error.max_position},
                                      {"max_rotation_deg", error.max_rotation_deg}};
    }
    if (!options.report.empty()) {
      std::ofstream out(options.report);
      out << report.dump(2) << "\n";
    }
    std::fprintf(stderr, "vicc_peer_odometry: %d frames, %d failures\n", processed, failures);
  } catch (const std::exception& error) {
    std::cerr << "vicc_peer_odometry: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
