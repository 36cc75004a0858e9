#pragma once
// The camera tracking pipeline of thesis Fig. 5.1, ROS-free: the node, the nodelet and the
// offline tools all drive this class.

#include <memory>
#include <optional>
#include <string>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "vicc_tracking/camera_model.hpp"
#include "vicc_tracking/depth_preprocessing.hpp"
#include "vicc_tracking/icp.hpp"
#include "vicc_tracking/imu_synchronizer.hpp"
#include "vicc_tracking/init_strategy.hpp"
#include "vicc_tracking/still_phase.hpp"

namespace vicc_tracking {

enum class TrackingState { kInitializing, kOk, kLost };
const char* toString(TrackingState state);

struct TrackerConfig {
  PreprocessingConfig preprocessing;
  IcpConfig icp;
  EkfConfig ekf;
  StillPhaseConfig still_phase;
  SynchronizerConfig synchronizer;
  InitStrategyType init_strategy = InitStrategyType::kEkf;
  /// Wait for the IMU still phase before tracking (needed by ekf/imu; gives a gravity-aligned
  /// map for all strategies). Without it, identity/constant_velocity start at the first frame.
  bool wait_for_imu = true;
  void validate() const;
};

struct StageTimings {
  double preprocessing_ms = 0.0;
  double prediction_ms = 0.0;
  double icp_ms = 0.0;
  double total_ms = 0.0;
};

struct FrameReport {
  bool accepted = true;  ///< false: frame dropped (see message), nothing changed
  std::string message;   ///< why a frame was dropped or tracking was lost
  double stamp = 0.0;
  int frame_index = -1;  ///< index among tracked frames (-1 while initializing)
  TrackingState state = TrackingState::kInitializing;
  Eigen::Isometry3d camera_pose = Eigen::Isometry3d::Identity();    ///< T_map_camera
  Eigen::Isometry3d initial_guess = Eigen::Isometry3d::Identity();  ///< T_map_camera
  IcpResult icp;
  double init_error_position = 0.0;  ///< |guess - result|, m
  double init_error_rotation_deg = 0.0;
  double identity_error_position = 0.0;  ///< |previous pose - result|: what identity init misses
  double identity_error_rotation_deg = 0.0;
  StageTimings timings;
  bool aligned_to_model = false;  ///< ICP reference was a model prediction (frame-to-model)
  /// ICP against the model failed and the frame was aligned to the previous frame instead.
  bool model_fallback = false;
  bool tracked() const { return accepted && state != TrackingState::kInitializing; }
};

class Tracker {
 public:
  /// imu_to_camera = T_imu_camera, the pose of the camera frame in the IMU frame (tf_static).
  Tracker(const TrackerConfig& config, const Eigen::Isometry3d& imu_to_camera);

  void setCamera(const CameraModel& camera);
  bool hasCamera() const { return preprocessor_.hasCamera(); }
  /// The calibration set last (hasCamera() says whether there is one).
  const CameraModel& camera() const { return preprocessor_.camera(); }

  /// A rejected reading (duplicate, out of order, NaN) is reported and ignored; a clock jump
  /// backwards (a looping bag) resets the tracker.
  ImuAddResult addImu(const ImuSample& sample);

  /// Processes one depth frame. Throws std::invalid_argument for an image that does not fit
  /// the camera (wrong type or size); the tracker state is unchanged then.
  FrameReport addDepth(double stamp, const cv::Mat& raw_depth);

  /// The pyramid of the frame addDepth() just tracked, for fusion. Valid until the next
  /// addDepth(); empty before tracking starts.
  const DepthPyramid& currentFrame() const {
    return reference_is_model_ ? last_frame_ : reference_;
  }

  /// Frame-to-model tracking: the next frame is aligned to `prediction` (the model rendered
  /// at the last camera pose, laid out like currentFrame()) instead of to the last frame.
  /// Returns false, keeping frame-to-frame, when not tracking or the layout does not match.
  /// Should ICP against the model fail, the frame is aligned to the previous frame instead.
  bool useModelPrediction(DepthPyramid&& prediction);

  /// Tuning changes while running (dynamic_reconfigure), from the next frame on. Throw
  /// std::invalid_argument for an invalid config; nothing changes then.
  void setIcpConfig(const IcpConfig& icp);
  void setEkfConfig(const EkfConfig& ekf);

  void reset();
  TrackingState state() const { return state_; }
  const TrackerConfig& config() const { return config_; }
  /// Set while initializing when the still phase saw motion.
  std::string calibrationWarning() const { return still_phase_.motionWarning(); }
  const ImuCalibration& calibration() const { return calibration_; }

 private:
  void startTracking(FrameReport& report, DepthPyramid&& pyramid);
  Eigen::Isometry3d gravityAlignedStart() const;

  TrackerConfig config_;
  Eigen::Isometry3d imu_to_camera_;
  DepthPreprocessor preprocessor_;
  ProjectiveIcp icp_;
  StillPhaseCalibrator still_phase_;
  ImuDepthSynchronizer synchronizer_;
  std::unique_ptr<InitStrategy> strategy_;
  ImuCalibration calibration_;
  bool imu_seen_ = false;

  TrackingState state_ = TrackingState::kInitializing;
  int frame_index_ = -1;
  std::optional<double> last_stamp_;
  Eigen::Isometry3d last_camera_pose_ = Eigen::Isometry3d::Identity();
  DepthPyramid reference_;
  bool reference_is_model_ = false;
  DepthPyramid last_frame_;  ///< the previous frame while reference_ is a model prediction
};

/// Translation (m) and rotation (deg) between two poses.
struct PoseDifference {
  double translation = 0.0;
  double rotation_deg = 0.0;
};
PoseDifference poseDifference(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b);

}  // namespace vicc_tracking
