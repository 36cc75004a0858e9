// The IMU-based initial guesses under constant acceleration: the velocity at the last tracked
// pose must come from the IMU steps between the last two poses, not from the backward
// difference of their positions (which is the velocity half an interval earlier).
#include <gtest/gtest.h>

#include <cmath>

#include "vicc_tracking/init_strategy.hpp"
#include "vicc_tracking/strapdown.hpp"

using namespace vicc_tracking;

namespace {

const Eigen::Vector3d kGravityMap(0.0, 0.0, -9.80665);

/// Analytic hand-held-like motion: constant body rate, constant map acceleration of ~4 m/s^2
/// (the simulated hen scenarios peak at about 5), non-zero start velocity.
struct AcceleratedMotion {
  Eigen::Quaterniond start =
      Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()));
  Eigen::Vector3d body_rate{0.8, -0.5, 1.2};
  Eigen::Vector3d start_velocity{0.2, 0.1, -0.05};
  Eigen::Vector3d acceleration{3.0, -2.0, 1.0};

  Eigen::Quaterniond orientation(double t) const {
    return start *
           Eigen::Quaterniond(Eigen::AngleAxisd(body_rate.norm() * t, body_rate.normalized()));
  }
  Eigen::Vector3d position(double t) const {
    return start_velocity * t + 0.5 * acceleration * t * t;
  }
  Eigen::Vector3d velocity(double t) const { return start_velocity + acceleration * t; }
  Eigen::Isometry3d pose(double t) const {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = orientation(t).toRotationMatrix();
    pose.translation() = position(t);
    return pose;
  }
  /// Noise-free REP-145 readings over [t0, t1] at 200 Hz, each held over its step.
  std::vector<ImuStep> steps(double t0, double t1) const {
    std::vector<ImuStep> result;
    const int count = static_cast<int>(std::lround((t1 - t0) * 200.0));
    const double dt = (t1 - t0) / count;
    for (int k = 0; k < count; ++k) {
      ImuStep step;
      step.angular_velocity = body_rate;
      step.linear_acceleration = orientation(t0 + k * dt).inverse() * (acceleration - kGravityMap);
      step.dt = dt;
      result.push_back(step);
    }
    return result;
  }
};

InitContext makeContext() {
  InitContext context;  // no bias; at rest the IMU reads +g in the map
  context.gravity_map = -kGravityMap;
  return context;
}

/// The thesis's EKF noise (config/tracker_thesis.yaml): the correction lands (almost) on the
/// virtual measurement, so the guess shows the measurement's error.
InitContext thesisNoiseContext() {
  InitContext context = makeContext();
  context.ekf = EkfConfig::thesisNoise();
  return context;
}

// 1/2 of 15 Hz: the frame-skipping case of thesis Tables 5.2-5.5.
constexpr double kInterval = 2.0 / 15.0;

TEST(InitStrategyTest, VelocityAtIntervalEndIsExactUnderConstantAcceleration) {
  const AcceleratedMotion motion;
  const InitContext context = makeContext();
  const double t0 = 0.3, t1 = t0 + kInterval;
  const Eigen::Vector3d velocity = velocityAtIntervalEnd(
      motion.orientation(t0), motion.position(t0), motion.position(t1), kInterval,
      motion.steps(t0, t1), context.calibration, context.gravity_map);
  EXPECT_LT((velocity - motion.velocity(t1)).norm(), 1e-9);
  // The backward difference is the velocity in the middle of the interval.
  const Eigen::Vector3d backward = (motion.position(t1) - motion.position(t0)) / kInterval;
  EXPECT_LT((backward - motion.velocity(t1 - 0.5 * kInterval)).norm(), 1e-9);
  // Without steps there is nothing better than the backward difference.
  EXPECT_LT((velocityAtIntervalEnd(motion.orientation(t0), motion.position(t0), motion.position(t1),
                                   kInterval, {}, context.calibration, context.gravity_map) -
             backward)
                .norm(),
            1e-12);
}

/// Runs a strategy over three intervals with ground-truth poses fed back as tracking results;
/// returns the position error of the last guess.
double lastGuessPositionError(InitStrategyType type, const InitContext& context = makeContext(),
                              const AcceleratedMotion& motion = AcceleratedMotion(),
                              double start = 0.2) {
  std::unique_ptr<InitStrategy> strategy = makeInitStrategy(type, context);
  double t = start;
  strategy->start(t, motion.pose(t));
  Eigen::Isometry3d guess = Eigen::Isometry3d::Identity();
  for (int interval = 0; interval < 3; ++interval) {
    const double next = t + kInterval;
    guess = strategy->predict(next, motion.steps(t, next));
    strategy->update(next, motion.pose(next));
    t = next;
  }
  return (guess.translation() - motion.position(t)).norm();
}

TEST(InitStrategyTest, ImuIntegrationPredictsTheTranslationUnderAcceleration) {
  // The backward-difference velocity missed a * T / 2, i.e. a * T^2 / 2 = 3.3 cm here.
  EXPECT_LT(lastGuessPositionError(InitStrategyType::kImu), 1e-6);
}

TEST(InitStrategyTest, EkfVirtualMeasurementExtrapolatesFromTheVelocityAtTheLastPose) {
  // With the thesis's R the corrected translation is p^e = T v_i (Eq. 5.15), which misses
  // a T^2 / 2 under constant acceleration; the lagging Eq. 5.10 velocity doubled that.
  const double half_a_t2 = 0.5 * AcceleratedMotion().acceleration.norm() * kInterval * kInterval;
  EXPECT_LT(lastGuessPositionError(InitStrategyType::kEkf, thesisNoiseContext()), 1.05 * half_a_t2);
}

TEST(InitStrategyTest, EkfWithTheDefaultNoiseTrustsTheImuMoreThanTheExtrapolation) {
  // From rest (the still phase, so the filter's zero start velocity is right) under constant
  // acceleration: the default (IMU-derived) noise follows the noise-free IMU more than the
  // extrapolation, which the thesis's noise follows.
  AcceleratedMotion from_rest;
  from_rest.start_velocity.setZero();
  const double half_a_t2 = 0.5 * from_rest.acceleration.norm() * kInterval * kInterval;
  const double with_defaults =
      lastGuessPositionError(InitStrategyType::kEkf, makeContext(), from_rest, 0.0);
  const double with_thesis =
      lastGuessPositionError(InitStrategyType::kEkf, thesisNoiseContext(), from_rest, 0.0);
  EXPECT_LT(with_defaults, 0.5 * half_a_t2) << "thesis noise: " << with_thesis;
  EXPECT_LT(with_defaults, 0.5 * with_thesis);
}

TEST(InitStrategyTest, EkfWithTheBackwardDifferenceOfEq510StillAvailable) {
  InitContext context = thesisNoiseContext();
  context.ekf.imu_aided_virtual_velocity = false;
  const double a_t2 = AcceleratedMotion().acceleration.norm() * kInterval * kInterval;
  EXPECT_GT(lastGuessPositionError(InitStrategyType::kEkf, context), 0.9 * a_t2);
}

}  // namespace
