#pragma once
// Strapdown integration of IMU readings (thesis 2.3).

#include <vector>

#include <Eigen/Geometry>

#include "vicc_tracking/imu_types.hpp"
#include "vicc_tracking/quaternion_math.hpp"

namespace vicc_tracking {

/// Closed-form orientation step for constant angular velocity (Eq. 2.15):
/// q_{k+1} = q_k (x) (cos(|w|dt/2), sin(|w|dt/2) w/|w|).
Eigen::Quaterniond integrateGyroClosedForm(const Eigen::Quaterniond& q,
                                           const Eigen::Vector3d& angular_velocity, double dt);

/// Pose and velocity of the IMU body in the gravity-aligned reference frame.
struct StrapdownState {
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
};

/// One step of Eq. 2.10-2.12 with the closed-form rotation: the bias-corrected gyro
/// rotates the body, the specific force rotated into the reference frame minus the
/// reference-frame rest reading gravity_ref gives the acceleration.
StrapdownState strapdownStep(const StrapdownState& state, const ImuStep& step,
                             const ImuCalibration& calibration,
                             const Eigen::Vector3d& gravity_ref);

/// Velocity at the end of an interval whose start and end positions are known (two tracked
/// poses) from the IMU steps recorded over it. Strapdown integration is linear in the start
/// velocity: p_end = p_start + v_start * T + s and v_end = v_start + a, where s and a are what
/// the steps add when integrated from rest (from start_orientation). Hence
///   v_end = (p_end - p_start - s) / T + a,
/// which is exact for the integration above. The backward difference (p_end - p_start) / T
/// is the mean velocity over the interval, i.e. the velocity half an interval earlier: under
/// acceleration it lags by a * T / 2. Without steps the result is that backward difference;
/// T <= 0 gives zero.
Eigen::Vector3d velocityAtIntervalEnd(const Eigen::Quaterniond& start_orientation,
                                      const Eigen::Vector3d& start_position,
                                      const Eigen::Vector3d& end_position, double interval,
                                      const std::vector<ImuStep>& steps,
                                      const ImuCalibration& calibration,
                                      const Eigen::Vector3d& gravity_ref);

}  // namespace vicc_tracking
