// vicc_reconstruct: runs the tracking pipeline over a depth + IMU recording. See --help.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>

#include "reconstruct_options.hpp"
#include "reconstruct_report.hpp"
#include "vicc_fusion/cloud_accumulator.hpp"
#include "vicc_tracking/ros/conversions.hpp"
#include "vicc_tracking/ros/rig_bag.hpp"
#include "vicc_tracking/tracker.hpp"
#include "vicc_tracking/tracking_statistics.hpp"
#include "vicc_tracking/trajectory_error.hpp"
#include "vicc_tracking/tum_trajectory.hpp"

namespace {

using Clock = std::chrono::steady_clock;
constexpr int kCloudFrameStride = 5;  // neighbouring frames see the same surface
constexpr int kMaxRepeatedWarnings = 5;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

class Reconstruction {
 public:
  Reconstruction(const vicc_fusion::ReconstructOptions& options, const vicc_tracking::RigBag& bag)
      : options_(options), bag_(bag) {
    config_.init_strategy = options.init;
    config_.preprocessing.pyramid_levels = options.levels;
    const bool has_imu = !bag.imuSamples().empty();
    if (vicc_tracking::needsImu(options.init) && !has_imu) {
      throw std::runtime_error("--init " + vicc_tracking::toString(options.init) +
                               " needs IMU data, but the bag has none (try --init identity)");
    }
    config_.wait_for_imu = has_imu;
    Eigen::Isometry3d imu_to_camera = Eigen::Isometry3d::Identity();
    if (has_imu) {
      if (!bag.imuToCamera()) {
        throw std::runtime_error("no IMU -> camera extrinsic (" + bag.imuFrame() + " -> " +
                                 bag.cameraFrame() + ") on /tf_static in the bag");
      }
      imu_to_camera = *bag.imuToCamera();
    }
    tracker_ = std::make_unique<vicc_tracking::Tracker>(config_, imu_to_camera);
    if (!options.cloud_path.empty()) {
      vicc_tracking::PreprocessingConfig cloud_preprocessing = config_.preprocessing;
      cloud_preprocessing.pyramid_levels = 1;
      cloud_preprocessor_ = std::make_unique<vicc_tracking::DepthPreprocessor>(cloud_preprocessing);
      cloud_ =
          std::make_unique<vicc_fusion::CloudAccumulator>(vicc_fusion::CloudAccumulatorConfig{});
    }
  }

  void run() {
    start_ = Clock::now();
    bag_.forEachDepthFrame(
        [this](const sensor_msgs::ImageConstPtr& image,
               const sensor_msgs::CameraInfoConstPtr& info) { onFrame(image, info); });
    run_.wall_time_s = secondsSince(start_);
    if (!options_.quiet) printProgress(true);
  }

  void writeOutputs() {
    if (!options_.trajectory_path.empty()) {
      vicc_tracking::writeTumTrajectory(options_.trajectory_path, trajectory_);
    }
    if (cloud_) {
      const auto cloud = cloud_->cloud();
      run_.cloud_points = cloud.size();
      vicc_fusion::saveCloudPly(options_.cloud_path, cloud);
    }
    run_.depth_topic = bag_.topics().depth;
    run_.info_topic = bag_.topics().camera_info;
    run_.imu_topic = bag_.topics().imu;
    run_.depth_frames_in_bag = bag_.depthFrameCount();
    if (!options_.ground_truth_path.empty()) {
      run_.ground_truth_error = vicc_tracking::compareTrajectories(
          trajectory_, vicc_tracking::readTumTrajectory(options_.ground_truth_path));
      std::fprintf(stderr,
                   "vicc_reconstruct: against ground truth (%zu poses): RMSE %.4f m, max %.4f m, "
                   "max %.3f deg\n",
                   run_.ground_truth_error->matched, run_.ground_truth_error->rmse_position,
                   run_.ground_truth_error->max_position,
                   run_.ground_truth_error->max_rotation_deg);
    }
    const nlohmann::json report = vicc_fusion::makeReport(options_, run_, statistics_);
    if (!options_.report_path.empty()) {
      std::ofstream out(options_.report_path);
      out << report.dump(2) << "\n";
      if (!out) throw std::runtime_error("cannot write " + options_.report_path);
    }
    std::fprintf(stderr,
                 "vicc_reconstruct: %d frames tracked, %d lost, %d initializing, %d dropped; "
                 "ICP iterations %.2f ± %.2f; median %.2f ms per frame\n",
                 statistics_.framesTracked(), statistics_.framesLost(),
                 statistics_.framesInitializing(), statistics_.framesDropped(),
                 statistics_.iterations().mean, statistics_.iterations().stddev,
                 statistics_.totalMs().median);
  }

 private:
  void warn(const std::string& message) {
    if (++warnings_ <= kMaxRepeatedWarnings) {
      std::fprintf(stderr, "\nvicc_reconstruct: warning: %s\n", message.c_str());
    } else if (warnings_ == kMaxRepeatedWarnings + 1) {
      std::fprintf(stderr, "\nvicc_reconstruct: further warnings suppressed\n");
    }
  }

  void feedImuUpTo(double stamp) {
    const auto& samples = bag_.imuSamples();
    while (next_imu_ < samples.size() && samples[next_imu_].stamp <= stamp) {
      tracker_->addImu(samples[next_imu_++]);
    }
  }

  void onFrame(const sensor_msgs::ImageConstPtr& image,
               const sensor_msgs::CameraInfoConstPtr& info) {
    const size_t index = depth_index_++;
    const double stamp = image->header.stamp.toSec();
    feedImuUpTo(stamp);
    if (index % options_.frame_step != 0) {
      ++run_.depth_frames_skipped;
      return;
    }
    if (!info) {
      warn("depth frame before any camera_info; skipped");
      return;
    }
    if (info != last_info_) {
      const bool changed = !last_info_ || info->K != last_info_->K || info->D != last_info_->D ||
                           info->width != last_info_->width || info->height != last_info_->height ||
                           info->distortion_model != last_info_->distortion_model;
      try {
        if (changed) {
          const vicc_tracking::CameraModel camera = vicc_tracking::cameraModelFromInfo(*info);
          tracker_->setCamera(camera);
          if (cloud_preprocessor_) cloud_preprocessor_->setCamera(camera);
        }
        last_info_ = info;
      } catch (const std::exception& error) {
        warn(std::string("invalid camera_info: ") + error.what());
        if (!tracker_->hasCamera()) return;
      }
    }
    vicc_tracking::FrameReport report;
    try {
      report = tracker_->addDepth(stamp, vicc_tracking::depthImageView(*image));
    } catch (const std::exception& error) {
      warn(std::string("depth frame dropped: ") + error.what());
      report.accepted = false;
    }
    if (!report.accepted && !report.message.empty()) warn("depth frame dropped: " + report.message);
    statistics_.add(report);
    if (report.tracked()) {
      trajectory_.push_back({stamp, report.camera_pose});
      if (cloud_ && report.state == vicc_tracking::TrackingState::kOk &&
          tracked_for_cloud_++ % kCloudFrameStride == 0) {
        const auto pyramid = cloud_preprocessor_->process(vicc_tracking::depthImageView(*image));
        cloud_->addFrame(pyramid.front(), report.camera_pose);
      }
    }
    if (!options_.quiet && secondsSince(last_progress_) > 1.0) printProgress(false);
  }

  void printProgress(bool final_line) {
    last_progress_ = Clock::now();
    const double elapsed = secondsSince(start_);
    std::fprintf(stderr, "\rvicc_reconstruct: frame %zu/%zu, tracked %d, lost %d, %.0f frames/s%s",
                 depth_index_, bag_.depthFrameCount(), statistics_.framesTracked(),
                 statistics_.framesLost(), elapsed > 0 ? statistics_.framesSeen() / elapsed : 0.0,
                 final_line ? "\n" : "");
  }

  const vicc_fusion::ReconstructOptions& options_;
  const vicc_tracking::RigBag& bag_;
  vicc_tracking::TrackerConfig config_;
  std::unique_ptr<vicc_tracking::Tracker> tracker_;
  std::unique_ptr<vicc_tracking::DepthPreprocessor> cloud_preprocessor_;
  std::unique_ptr<vicc_fusion::CloudAccumulator> cloud_;
  vicc_tracking::TrackingStatistics statistics_;
  std::vector<vicc_tracking::TimedPose> trajectory_;
  vicc_fusion::ReconstructRun run_;
  sensor_msgs::CameraInfoConstPtr last_info_;
  size_t depth_index_ = 0;
  size_t next_imu_ = 0;
  int tracked_for_cloud_ = 0;
  int warnings_ = 0;
  Clock::time_point start_ = Clock::now();
  Clock::time_point last_progress_ = Clock::now();
};

}  // namespace

int main(int argc, char** argv) {
  vicc_fusion::ReconstructOptions options;
  try {
    if (!vicc_fusion::parseReconstructOptions(argc, argv, options, std::cout)) return 0;
  } catch (const std::exception& error) {
    std::cerr << "vicc_reconstruct: " << error.what() << "\n\n";
    vicc_fusion::printReconstructUsage(std::cerr);
    return 2;
  }
  try {
    const vicc_tracking::RigBag bag(options.bag_path,
                                    {options.depth_topic, options.info_topic, options.imu_topic});
    std::fprintf(stderr, "vicc_reconstruct: %s: %zu depth frames on %s, %zu IMU readings on %s\n",
                 options.bag_path.c_str(), bag.depthFrameCount(), bag.topics().depth.c_str(),
                 bag.imuSamples().size(),
                 bag.topics().imu.empty() ? "(none)" : bag.topics().imu.c_str());
    if (bag.invalidImuReadings() > 0) {
      std::fprintf(stderr, "vicc_reconstruct: warning: %d invalid IMU readings skipped\n",
                   bag.invalidImuReadings());
    }
    Reconstruction reconstruction(options, bag);
    reconstruction.run();
    reconstruction.writeOutputs();
  } catch (const std::exception& error) {
    std::cerr << "vicc_reconstruct: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
