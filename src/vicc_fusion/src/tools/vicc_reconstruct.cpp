// vicc_reconstruct: runs the tracking pipeline over a depth + IMU recording. See --help.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>

#include "reconstruct_options.hpp"
#include "reconstruct_report.hpp"
#include "vicc_fusion/frame_to_model.hpp"
#include "vicc_fusion/surfel_io.hpp"
#include "vicc_tracking/frame_memory.hpp"
#include "vicc_tracking/ros/conversions.hpp"
#include "vicc_tracking/ros/rig_bag.hpp"
#include "vicc_tracking/tracker.hpp"
#include "vicc_tracking/tracking_statistics.hpp"
#include "vicc_tracking/trajectory_error.hpp"
#include "vicc_tracking/tum_trajectory.hpp"

namespace {

using Clock = std::chrono::steady_clock;
using ReconstructRunFusion = vicc_fusion::ReconstructRun::Fusion;
constexpr int kMaxRepeatedWarnings = 5;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

class Reconstruction {
 public:
  Reconstruction(const vicc_fusion::ReconstructOptions& options, const vicc_tracking::RigBag& bag)
      : options_(options),
        bag_(bag),
        config_(options.tracker),
        gray_preprocessor_(options.tracker.preprocessing) {
    const bool has_imu = !bag.imuSamples().empty();
    if (vicc_tracking::needsImu(options.init) && !has_imu) {
      throw std::runtime_error("--init " + vicc_tracking::toString(options.init) +
                               " needs IMU data, but the bag has none (try --init identity)");
    }
    config_.wait_for_imu = has_imu && options.tracker.wait_for_imu;
    Eigen::Isometry3d imu_to_camera = Eigen::Isometry3d::Identity();
    if (has_imu) {
      if (!bag.imuToCamera()) {
        throw std::runtime_error("no IMU -> camera extrinsic (" + bag.imuFrame() + " -> " +
                                 bag.cameraFrame() + ") on /tf_static in the bag");
      }
      imu_to_camera = *bag.imuToCamera();
    }
    tracker_ = std::make_unique<vicc_tracking::Tracker>(config_, imu_to_camera);
    if (options.fusion) {
      model_ = std::make_unique<vicc_fusion::FrameToModel>(options.model);
      run_.fusion.emplace();
    }
  }

  void run() {
    start_ = Clock::now();
    bag_.forEachFrame(
        [this](const sensor_msgs::ImageConstPtr& image, const sensor_msgs::CameraInfoConstPtr& info,
               const sensor_msgs::ImageConstPtr& gray) { onFrame(image, info, gray); });
    run_.wall_time_s = secondsSince(start_);
    if (!options_.quiet) printProgress(true);
  }

  void writeOutputs() {
    if (!options_.trajectory_path.empty()) {
      vicc_tracking::writeTumTrajectory(options_.trajectory_path, trajectory_);
    }
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
    if (model_) {
      const vicc_fusion::SurfelFusion& fusion = model_->fusion();
      ReconstructRunFusion& summary = *run_.fusion;
      summary.stable = fusion.stableCount();
      summary.unstable = fusion.unstableCount();
      summary.memory_bytes = fusion.memoryBytes();
      summary.fusion_ms = vicc_tracking::summarize(fusion_ms_);
      summary.model_prediction_ms = vicc_tracking::summarize(model_prediction_ms_);
      summary.pipeline_ms = vicc_tracking::summarize(pipeline_ms_);
      const vicc_fusion::SurfelVector stable = fusion.stableSurfels();
      size_t with_intensity = 0;
      for (const vicc_fusion::Surfel& surfel : stable)
        with_intensity += !std::isnan(surfel.intensity);
      run_.stable_with_intensity =
          stable.empty() ? 0.0 : static_cast<double>(with_intensity) / stable.size();
      if (!bag_.topics().intensity.empty()) {
        std::fprintf(stderr,
                     "vicc_reconstruct: intensity from %s: %d frames with, %d without; %.1f %% of "
                     "the stable surfels have one\n",
                     bag_.topics().intensity.c_str(), run_.frames_with_intensity,
                     run_.frames_without_intensity, run_.stable_with_intensity * 100);
      }
      if (!options_.truth_surface_path.empty() && run_.ground_truth_error) {
        run_.accuracy = vicc_fusion::evaluateModel(
            stable, vicc_fusion::loadTruthSurface(options_.truth_surface_path),
            run_.ground_truth_error->alignment);
        std::fprintf(stderr,
                     "vicc_reconstruct: model vs true surface: mean %.2f mm, 95%% %.2f mm, "
                     "completeness %.1f %% (within %.0f mm)\n",
                     run_.accuracy->mean_distance * 1e3, run_.accuracy->p95_distance * 1e3,
                     run_.accuracy->completeness * 100, run_.accuracy->completeness_radius * 1e3);
      }
      if (!options_.cloud_path.empty()) {
        vicc_fusion::saveSurfelsPly(options_.cloud_path, stable);
        run_.cloud_points = stable.size();
      }
      if (!options_.mesh_path.empty()) {
        const pcl::PolygonMesh mesh = vicc_fusion::meshSurfels(stable);
        vicc_fusion::saveMeshPly(options_.mesh_path, mesh);
        run_.mesh_triangles = mesh.polygons.size();
      }
      std::fprintf(stderr,
                   "vicc_reconstruct: model: %zu stable + %zu unstable surfels (%.1f MB); "
                   "median fusion %.2f ms, model prediction %.2f ms, pipeline %.2f ms per frame "
                   "(%.0f frames/s); %d of %d frames aligned to the model\n",
                   summary.stable, summary.unstable, summary.memory_bytes / 1e6,
                   summary.fusion_ms.median, summary.model_prediction_ms.median,
                   summary.pipeline_ms.median,
                   summary.pipeline_ms.median > 0 ? 1000.0 / summary.pipeline_ms.median : 0.0,
                   summary.frames_aligned_to_model, statistics_.framesTracked());
    }
    run_.depth_topic = bag_.topics().depth;
    run_.info_topic = bag_.topics().camera_info;
    run_.imu_topic = bag_.topics().imu;
    run_.intensity_topic = bag_.topics().intensity;
    run_.depth_frames_in_bag = bag_.depthFrameCount();
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

  void onFrame(const sensor_msgs::ImageConstPtr& image, const sensor_msgs::CameraInfoConstPtr& info,
               const sensor_msgs::ImageConstPtr& gray) {
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
      try {
        const vicc_tracking::CameraModel camera = vicc_tracking::cameraModelFromInfo(*info);
        if (!camera_ || *camera_ != camera) {  // the one calibration test of every node
          tracker_->setCamera(camera);
          gray_preprocessor_.setCamera(camera);
          camera_ = camera;
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
    if (report.tracked()) trajectory_.push_back({stamp, report.camera_pose});
    if (report.accepted && report.state == vicc_tracking::TrackingState::kLost) {
      char where[64];
      std::snprintf(where, sizeof(where), "frame %zu (t = %.3f): ", index, stamp);
      warn(where + report.message);
    }
    if (report.aligned_to_model && run_.fusion) ++run_.fusion->frames_aligned_to_model;
    if (report.model_fallback && run_.fusion) ++run_.fusion->frames_model_fallback;
    if (model_) fuse(report, gray);
    if (!options_.quiet && secondsSince(last_progress_) > 1.0) printProgress(false);
  }

  void fuse(const vicc_tracking::FrameReport& report, const sensor_msgs::ImageConstPtr& gray) {
    cv::Mat1f intensity;
    if (gray && !bag_.topics().intensity.empty()) {
      try {
        intensity = gray_preprocessor_.undistortIntensity(vicc_tracking::intensityImageView(*gray));
      } catch (const std::exception& error) {
        warn(std::string("gray image not used: ") + error.what());
      }
    }
    const vicc_fusion::FrameToModelStep step =
        model_->afterFrame(*tracker_, report, intensity.empty() ? nullptr : &intensity);
    if (!step.fused) return;
    if (!bag_.topics().intensity.empty()) {
      ++(intensity.empty() ? run_.frames_without_intensity : run_.frames_with_intensity);
    }
    ReconstructRunFusion& summary = *run_.fusion;
    ++summary.frames_fused;
    summary.surfels_refused += step.fusion.refused;
    summary.merged += step.fusion.merged;
    summary.confirmed += step.fusion.confirmed;
    summary.added += step.fusion.added;
    summary.removed_unconfirmed += step.fusion.removed_unconfirmed;
    summary.removed_free_space += step.fusion.removed_free_space;
    summary.merged_duplicates += step.fusion.merged_duplicates;
    if (step.fusion.refused > 0 && summary.surfels_refused == step.fusion.refused) {
      warn("the model reached its maximum of " +
           std::to_string(model_->config().fusion.max_surfels) +
           " surfels: new surface is no longer added");
    }
    fusion_ms_.push_back(step.fusion_ms);
    model_prediction_ms_.push_back(step.prediction_ms);
    pipeline_ms_.push_back(report.timings.total_ms + step.fusion_ms + step.prediction_ms);
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
  /// The tracker's preprocessing for the gray image: the same undistorted grid as the depth.
  vicc_tracking::DepthPreprocessor gray_preprocessor_;
  std::unique_ptr<vicc_tracking::Tracker> tracker_;
  std::unique_ptr<vicc_fusion::FrameToModel> model_;
  std::vector<double> fusion_ms_, model_prediction_ms_, pipeline_ms_;
  vicc_tracking::TrackingStatistics statistics_;
  std::vector<vicc_tracking::TimedPose> trajectory_;
  vicc_fusion::ReconstructRun run_;
  sensor_msgs::CameraInfoConstPtr last_info_;
  std::optional<vicc_tracking::CameraModel> camera_;  ///< the calibration in use
  size_t depth_index_ = 0;
  size_t next_imu_ = 0;
  int warnings_ = 0;
  Clock::time_point start_ = Clock::now();
  Clock::time_point last_progress_ = Clock::now();
};

}  // namespace

int main(int argc, char** argv) {
  vicc_tracking::keepFreedFrameMemory();
  vicc_fusion::ReconstructOptions options;
  try {
    if (!vicc_fusion::parseReconstructOptions(argc, argv, options, std::cout)) return 0;
  } catch (const std::exception& error) {
    std::cerr << "vicc_reconstruct: " << error.what() << "\n\n";
    vicc_fusion::printReconstructUsage(std::cerr);
    return 2;
  }
  try {
    const vicc_tracking::RigBag bag(options.bag_path, {options.depth_topic, options.info_topic,
                                                       options.imu_topic, options.intensity_topic});
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
