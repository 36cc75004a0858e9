#pragma once
// How the ICP initial pose of a new depth frame is guessed (thesis 5.4 and its baselines).
// All strategies work on the IMU body pose T_map_imu; the tracker converts camera poses.

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "vicc_tracking/ekf.hpp"
#include "vicc_tracking/imu_types.hpp"
#include "vicc_tracking/virtual_measurement.hpp"

namespace vicc_tracking {

enum class InitStrategyType {
  kEkf,               ///< the thesis: EKF of IMU + extrapolated ICP poses
  kIdentity,          ///< KinectFusion: the previous pose
  kConstantVelocity,  ///< the previous frame-to-frame motion, scaled to the interval
  kImu,               ///< plain IMU integration (Niessner et al. 2014)
};

InitStrategyType initStrategyFromString(const std::string& name);
std::string toString(InitStrategyType type);
bool needsImu(InitStrategyType type);

class InitStrategy {
 public:
  virtual ~InitStrategy() = default;
  virtual InitStrategyType type() const = 0;

  /// The first tracked frame.
  virtual void start(double stamp, const Eigen::Isometry3d& imu_pose);
  /// Initial guess for the frame at stamp, from the IMU steps since the previous frame.
  virtual Eigen::Isometry3d predict(double stamp, const std::vector<ImuStep>& steps) = 0;
  /// The pose tracking settled on for that frame.
  virtual void update(double stamp, const Eigen::Isometry3d& imu_pose);
  /// New EKF noise values (dynamic_reconfigure); strategies without a filter ignore them.
  virtual void setEkfConfig(const EkfConfig& /*config*/) {}

 protected:
  PoseHistory history_;
};

struct InitContext {
  EkfConfig ekf;
  ImuCalibration calibration;
  Eigen::Vector3d gravity_map = Eigen::Vector3d(0.0, 0.0, 9.80665);  ///< g~ in the map frame
};

std::unique_ptr<InitStrategy> makeInitStrategy(InitStrategyType type, const InitContext& context);

}  // namespace vicc_tracking
