#include "vicc_tracking/tracker.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>

namespace vicc_tracking {
namespace {

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace

const char* toString(TrackingState state) {
  switch (state) {
    case TrackingState::kInitializing:
      return "initializing";
    case TrackingState::kOk:
      return "ok";
    case TrackingState::kLost:
      return "lost";
  }
  return "unknown";
}

void TrackerConfig::validate() const {
  preprocessing.validate();
  icp.validate();
  ekf.validate();
  still_phase.validate();
  synchronizer.validate();
  if (!wait_for_imu && needsImu(init_strategy)) {
    throw std::invalid_argument("init strategy '" + toString(init_strategy) +
                                "' needs the IMU: wait_for_imu must be true");
  }
}

PoseDifference poseDifference(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  const Eigen::Isometry3d delta = a.inverse() * b;
  PoseDifference difference;
  difference.translation = (a.translation() - b.translation()).norm();
  difference.rotation_deg = Eigen::AngleAxisd(delta.linear()).angle() * 180.0 / M_PI;
  return difference;
}

namespace {

/// Pose composition accumulates rounding; Isometry3d::inverse() assumes an exact rotation, so
/// without this a tiny scale error doubles with every frame (ref * ref^-T * ...).
Eigen::Isometry3d orthonormalized(const Eigen::Isometry3d& pose) {
  Eigen::Isometry3d result = pose;
  result.linear() = Eigen::Quaterniond(pose.linear()).normalized().toRotationMatrix();
  return result;
}

}  // namespace

Tracker::Tracker(const TrackerConfig& config, const Eigen::Isometry3d& imu_to_camera)
    : config_(config),
      imu_to_camera_(imu_to_camera),
      preprocessor_(config.preprocessing),
      icp_(config.icp),
      still_phase_(config.still_phase),
      synchronizer_(config.synchronizer) {
  config_.validate();
  if (!imu_to_camera_.matrix().allFinite()) {
    throw std::invalid_argument("IMU-to-camera transform is not finite");
  }
}

void Tracker::setCamera(const CameraModel& camera) { preprocessor_.setCamera(camera); }

void Tracker::setIcpConfig(const IcpConfig& icp) {
  icp_ = ProjectiveIcp(icp);  // validates
  config_.icp = icp;
}

void Tracker::setEkfConfig(const EkfConfig& ekf) {
  ekf.validate();
  if (strategy_) strategy_->setEkfConfig(ekf);
  config_.ekf = ekf;
}

bool Tracker::useModelPrediction(DepthPyramid&& prediction) {
  if (state_ != TrackingState::kOk || prediction.size() != reference_.size()) return false;
  for (size_t level = 0; level < prediction.size(); ++level) {
    const PinholeIntrinsics& a = prediction[level].intrinsics;
    const PinholeIntrinsics& b = reference_[level].intrinsics;
    if (a.width != b.width || a.height != b.height ||
        prediction[level].vertices.size() != reference_[level].vertices.size()) {
      return false;
    }
  }
  last_frame_ = std::move(reference_);  // kept for the fallback, not copied
  reference_ = std::move(prediction);
  reference_is_model_ = true;
  return true;
}

void Tracker::reset() {
  state_ = TrackingState::kInitializing;
  frame_index_ = -1;
  last_stamp_.reset();
  reference_.clear();
  reference_is_model_ = false;
  last_frame_.clear();
  strategy_.reset();
  still_phase_.reset();
  synchronizer_.reset();
  imu_seen_ = false;
}

ImuAddResult Tracker::addImu(const ImuSample& sample) {
  const ImuAddResult result = synchronizer_.add(sample);
  if (result == ImuAddResult::kClockJump) {
    reset();
    synchronizer_.add(sample);
    still_phase_.add(sample);
    imu_seen_ = true;
    return result;
  }
  const bool accepted = result == ImuAddResult::kAccepted || result == ImuAddResult::kFirst ||
                        result == ImuAddResult::kGap;
  if (accepted) {
    imu_seen_ = true;
    if (state_ == TrackingState::kInitializing) still_phase_.add(sample);
  }
  return result;
}

Eigen::Isometry3d Tracker::gravityAlignedStart() const {
  // Map z axis against gravity (the rest reading points up), map x along the camera's
  // optical axis projected onto the horizontal plane, map origin at the camera.
  Eigen::Matrix3d imu_to_map;
  if (imu_seen_) {
    const Eigen::Vector3d up_imu = calibration_.gravity_imu.normalized();
    const Eigen::Vector3d optical_axis_imu = imu_to_camera_.linear() * Eigen::Vector3d::UnitZ();
    Eigen::Vector3d forward_imu = optical_axis_imu - optical_axis_imu.dot(up_imu) * up_imu;
    if (forward_imu.norm() < 1e-6) {  // looking straight up or down: any heading will do
      forward_imu = up_imu.unitOrthogonal();
    }
    forward_imu.normalize();
    const Eigen::Vector3d left_imu = up_imu.cross(forward_imu);
    imu_to_map.row(0) = forward_imu.transpose();
    imu_to_map.row(1) = left_imu.transpose();
    imu_to_map.row(2) = up_imu.transpose();
  } else {
    // No IMU: assume a level camera (optical z forward, y down) for a z-up map.
    Eigen::Matrix3d camera_to_map;
    camera_to_map << 0, 0, 1, -1, 0, 0, 0, -1, 0;
    imu_to_map = camera_to_map * imu_to_camera_.linear().transpose();
  }
  Eigen::Isometry3d map_to_imu = Eigen::Isometry3d::Identity();
  map_to_imu.linear() = imu_to_map;
  map_to_imu.translation() = -(imu_to_map * imu_to_camera_.translation());
  return map_to_imu;  // T_map_imu with the camera at the map origin
}

void Tracker::startTracking(FrameReport& report, DepthPyramid&& pyramid) {
  if (imu_seen_) calibration_ = still_phase_.calibration();
  const Eigen::Isometry3d map_to_imu = gravityAlignedStart();
  InitContext context;
  context.ekf = config_.ekf;
  context.calibration = calibration_;
  context.gravity_map = map_to_imu.linear() * calibration_.gravity_imu;
  strategy_ = makeInitStrategy(config_.init_strategy, context);
  strategy_->start(report.stamp, map_to_imu);
  synchronizer_.discardBuffered();  // readings before the first frame belong to no interval

  state_ = TrackingState::kOk;
  frame_index_ = 0;
  last_camera_pose_ = map_to_imu * imu_to_camera_;
  reference_ = std::move(pyramid);
  reference_is_model_ = false;
  report.frame_index = 0;
  report.state = state_;
  report.camera_pose = last_camera_pose_;
  report.initial_guess = last_camera_pose_;
  report.icp.ok = true;
}

FrameReport Tracker::addDepth(double stamp, const cv::Mat& raw_depth) {
  const auto start = std::chrono::steady_clock::now();
  FrameReport report;
  report.stamp = stamp;
  report.state = state_;
  if (!std::isfinite(stamp)) {
    report.accepted = false;
    report.message = "non-finite stamp";
    return report;
  }
  if (last_stamp_) {
    if (stamp < *last_stamp_ - config_.synchronizer.clock_jump) {
      reset();  // a looping bag or restarted driver: start over with a new still phase
    } else if (stamp <= *last_stamp_) {
      report.accepted = false;
      report.message =
          stamp == *last_stamp_ ? "duplicated depth stamp" : "out-of-order depth stamp";
      return report;
    }
  }

  DepthPyramid pyramid = preprocessor_.process(raw_depth);  // throws on bad input
  report.timings.preprocessing_ms = millisecondsSince(start);

  if (state_ == TrackingState::kInitializing) {
    const bool imu_ready = imu_seen_ && still_phase_.complete();
    const bool may_start_without_imu = !config_.wait_for_imu && !imu_seen_;
    if (!imu_ready && !may_start_without_imu) {
      report.message = imu_seen_ ? "collecting still phase" : "waiting for IMU data";
      report.timings.total_ms = millisecondsSince(start);
      return report;
    }
    last_stamp_ = stamp;
    startTracking(report, std::move(pyramid));
    report.timings.total_ms = millisecondsSince(start);
    return report;
  }

  const auto prediction_start = std::chrono::steady_clock::now();
  const double interval = stamp - *last_stamp_;
  const std::vector<ImuStep> steps = synchronizer_.takeInterval(interval);
  const Eigen::Isometry3d guess =
      orthonormalized(strategy_->predict(stamp, steps) * imu_to_camera_);
  report.timings.prediction_ms = millisecondsSince(prediction_start);

  const auto icp_start = std::chrono::steady_clock::now();
  const Eigen::Isometry3d reference_pose = last_camera_pose_;
  report.icp = icp_.align(pyramid, reference_, reference_pose.inverse() * guess);
  report.aligned_to_model = reference_is_model_;
  if (!report.icp.ok && reference_is_model_ && !last_frame_.empty()) {
    // The model can miss what the last frame saw (holes, newly seen surface): a frame-to-frame
    // alignment is better than losing track.
    IcpResult fallback = icp_.align(pyramid, last_frame_, reference_pose.inverse() * guess);
    if (fallback.ok) {
      report.icp = std::move(fallback);
      report.aligned_to_model = false;
      report.model_fallback = true;
    }
  }
  report.timings.icp_ms = millisecondsSince(icp_start);

  report.initial_guess = guess;
  if (report.icp.ok) {
    report.camera_pose = orthonormalized(reference_pose * report.icp.pose);
    state_ = TrackingState::kOk;
  } else {
    // Keep the prediction rather than a result ICP itself distrusts.
    report.camera_pose = guess;
    report.message = "ICP failed: " + report.icp.failure_reason;
    state_ = TrackingState::kLost;
  }
  const PoseDifference init_error = poseDifference(guess, report.camera_pose);
  const PoseDifference identity_error = poseDifference(reference_pose, report.camera_pose);
  report.init_error_position = init_error.translation;
  report.init_error_rotation_deg = init_error.rotation_deg;
  report.identity_error_position = identity_error.translation;
  report.identity_error_rotation_deg = identity_error.rotation_deg;

  strategy_->update(stamp, report.camera_pose * imu_to_camera_.inverse());
  last_camera_pose_ = report.camera_pose;
  last_stamp_ = stamp;
  reference_ = std::move(pyramid);
  reference_is_model_ = false;
  last_frame_.clear();
  report.state = state_;
  report.frame_index = ++frame_index_;
  report.timings.total_ms = millisecondsSince(start);
  return report;
}

}  // namespace vicc_tracking
