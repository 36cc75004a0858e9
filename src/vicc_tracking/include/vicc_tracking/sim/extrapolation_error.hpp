#pragma once
// The error of the EKF's virtual measurements (thesis Eq. 5.13-5.15) against the simulator's
// ground truth: what R should be, and how it grows with the frame interval
// (docs/imu_noise.md, tool vicc_extrapolation_error).

#include <vector>

#include "vicc_tracking/sim/rig_simulator.hpp"

namespace vicc_tracking::sim {

struct ExtrapolationError {
  int frame_step = 1;
  double interval = 0.0;  ///< s between the processed depth frames
  int samples = 0;        ///< extrapolated intervals
  /// Mean squared error per component (the diagonal R of EkfConfig): quaternion part of the
  /// frame-to-frame rotation, velocity (m/s), translation (m).
  double rotation = 0.0;
  double velocity = 0.0;
  double position = 0.0;
};

/// Virtual measurements from the true IMU poses (and, as with imu_aided_virtual_velocity, the
/// true velocities) at every frame_step-th depth frame, compared with the true motion over
/// the next interval.
ExtrapolationError measureExtrapolationError(const RigSimulator& rig, int frame_step);

/// Least-squares slope of log(variance) over log(interval): the exponent k of
/// R(T) = R(T_ref) (T / T_ref)^k, for rotation, velocity and position.
struct IntervalExponents {
  double rotation = 0.0;
  double velocity = 0.0;
  double position = 0.0;
};
IntervalExponents fitIntervalExponents(const std::vector<ExtrapolationError>& errors);

}  // namespace vicc_tracking::sim
