#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Cholesky>

#include "vicc_tracking/ekf.hpp"

using namespace vicc_tracking;

namespace {

const Eigen::Vector3d kGravityMap(0.0, 0.0, -9.80665);

/// Analytic motion from rest: constant body angular velocity, constant map acceleration.
struct AnalyticMotion {
  Eigen::Quaterniond start =
      Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()));
  Eigen::Vector3d body_rate{0.3, -0.2, 0.5};
  Eigen::Vector3d acceleration{0.5, -0.3, 0.2};

  Eigen::Quaterniond orientation(double t) const {
    return start *
           Eigen::Quaterniond(Eigen::AngleAxisd(body_rate.norm() * t, body_rate.normalized()));
  }
  Eigen::Vector3d position(double t) const { return 0.5 * acceleration * t * t; }
  /// Noise-free REP-145 reading at the start of [t, t + dt], held over the step (the
  /// discretisation of Eq. 5.5, which rotates it with the orientation at the step's start).
  ImuStep reading(double t, double dt) const {
    ImuStep step;
    step.angular_velocity = body_rate;
    step.linear_acceleration = orientation(t).inverse() * (acceleration - kGravityMap);
    step.dt = dt;
    return step;
  }
};

Quat4 toQuat(const Eigen::Quaterniond& q) { return Quat4(q.w(), q.x(), q.y(), q.z()); }
Eigen::Quaterniond fromQuat(const Quat4& q) { return Eigen::Quaterniond(q[0], q[1], q[2], q[3]); }

/// The thesis's values (config/tracker_thesis.yaml): R far below P, so a correction lands
/// (almost) on the measurement, which the mechanics tests below use.
EkfConfig thesisNoise() { return EkfConfig::thesisNoise(); }

InitializationEkf makeEkf(const EkfConfig& config = thesisNoise()) {
  ImuCalibration calibration;  // no bias; at rest the IMU reads +g in the map
  return InitializationEkf(config, calibration, -kGravityMap);
}

constexpr double kInterval = 4.0 / 15.0;  // every 4th frame at 15 Hz

TEST(EkfTest, NoiseFreePredictionReproducesTheTrueRelativePose) {
  const AnalyticMotion motion;
  InitializationEkf ekf = makeEkf();
  ekf.start(toQuat(motion.start));
  const double dt = 1.0 / 200.0;
  const int steps = 40;  // 0.2 s: more than a depth interval at 1/4 of 15 Hz
  for (int k = 0; k < steps; ++k) ekf.predict(motion.reading(k * dt, dt));
  const double t = steps * dt;
  const EkfState& state = ekf.state();
  // q is the frame-to-frame rotation on top of the base orientation q_b.
  const Eigen::Quaterniond estimated = fromQuat(state.q_b) * fromQuat(state.q);
  EXPECT_LT(estimated.angularDistance(motion.orientation(t)) * 180.0 / M_PI, 0.01);
  EXPECT_LT((state.p - motion.position(t)).norm(), 1e-3);
  EXPECT_LT((state.v - motion.acceleration * t).norm(), 1e-3);
}

TEST(EkfTest, ProcessJacobianMatchesNumericalDerivativeForVelocityAndPosition) {
  const AnalyticMotion motion;
  InitializationEkf ekf = makeEkf();
  ekf.start(toQuat(motion.start));
  const ImuStep step = motion.reading(0.0, 0.01);
  for (int k = 0; k < 5; ++k) ekf.predict(step);  // a state with velocity and rotation
  const Matrix14d analytic = ekf.processJacobian(step);
  // p and v enter Eq. 5.5-5.6 linearly: d p'/d v = dt I, d v'/d v = I, d v'/d p = 0.
  const int kV = 4, kP = 7;
  const EkfState before = ekf.state();
  InitializationEkf moved = ekf;
  const double h = 1e-3;
  Vector14d shifted = before.toVector();
  shifted(kV) += h;
  // A copy with a shifted velocity predicts a shifted position: the finite difference.
  InitializationEkf probe = ekf;
  probe.correct(shifted, kInterval);  // R_v = 1e-6 << P: the correction lands (almost) on the shift
  const double applied = probe.state().v.x() - before.v.x();
  moved.predict(step);
  probe.predict(step);
  const double numerical = (probe.state().p.x() - moved.state().p.x()) / applied;
  EXPECT_NEAR(numerical, analytic(kP, kV), 1e-3 * step.dt);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(analytic(kP + i, kV + i), step.dt, 1e-12);
    EXPECT_NEAR(analytic(kV + i, kV + i), 1.0, 1e-12);
    for (int j = 0; j < 3; ++j) EXPECT_EQ(analytic(kV + i, kP + j), 0.0);
  }
  // Rotation block I + dt/2 R((0, w)) is orthogonal up to O(dt^2 |w|^2).
  const Eigen::Matrix4d rotation_block = analytic.block<4, 4>(0, 0);
  EXPECT_LT((rotation_block.transpose() * rotation_block - Eigen::Matrix4d::Identity()).norm(),
            step.dt * step.dt * step.angular_velocity.squaredNorm());
}

TEST(EkfTest, CorrectPullsTowardsTheMeasurementAndShrinksCovariance) {
  InitializationEkf ekf = makeEkf();
  ekf.start(identityQuat());
  ImuStep rest;
  rest.linear_acceleration = -kGravityMap;
  rest.dt = 0.005;
  for (int k = 0; k < 10; ++k) ekf.predict(rest);
  const double trace_before = ekf.covariance().trace();
  Vector14d measurement = ekf.state().toVector();
  measurement.segment<3>(4) = Eigen::Vector3d(0.2, 0.0, 0.0);  // a velocity the ICP poses show
  ekf.correct(measurement, kInterval);
  EXPECT_GT(ekf.state().v.x(), 0.19);  // R_v = 1e-6 is far below P: trust the measurement
  EXPECT_LT(ekf.covariance().trace(), trace_before);
}

TEST(EkfTest, ResetKeepsCovarianceSymmetricPositiveDefinite) {
  const AnalyticMotion motion;
  InitializationEkf ekf = makeEkf();
  ekf.start(toQuat(motion.start));
  const double dt = 1.0 / 200.0;
  for (int cycle = 0; cycle < 50; ++cycle) {
    for (int k = 0; k < 13; ++k) ekf.predict(motion.reading((cycle * 13 + k) * dt, dt));
    Vector14d measurement = ekf.state().toVector();
    measurement.segment<3>(4) += Eigen::Vector3d(0.01, -0.02, 0.005) * std::sin(cycle);
    ekf.correct(measurement, 13.0 / 200.0);
    ekf.reset(ekf.state().q_b);
    const Matrix14d& p = ekf.covariance();
    ASSERT_TRUE(p.allFinite());
    EXPECT_LT((p - p.transpose()).norm(), 1e-12 * p.norm()) << "cycle " << cycle;
    EXPECT_EQ(Eigen::LLT<Matrix14d>(p).info(), Eigen::Success) << "cycle " << cycle;
  }
}

TEST(EkfTest, MeasurementNoiseScalesWithAPowerOfTheInterval) {
  const EkfConfig config;  // the defaults: R at 4/15 s, exponent 3
  ASSERT_DOUBLE_EQ(config.measurement_noise_reference_interval, kInterval);
  ASSERT_DOUBLE_EQ(config.measurement_noise_interval_exponent, 3.0);
  const InitializationEkf ekf = makeEkf(config);
  const Matrix14d at_reference = ekf.measurementNoise(kInterval);
  EXPECT_DOUBLE_EQ(at_reference(0, 0), config.measurement_noise_rotation);
  EXPECT_DOUBLE_EQ(at_reference(4, 4), config.measurement_noise_velocity);
  EXPECT_DOUBLE_EQ(at_reference(7, 7), config.measurement_noise_position);
  EXPECT_DOUBLE_EQ(at_reference(10, 10), config.measurement_noise_base);
  // Every frame (1/15 s) is a quarter of the interval: R / 4^3 for the extrapolated parts,
  // the ICP orientation q_b unchanged.
  const Matrix14d every_frame = ekf.measurementNoise(kInterval / 4.0);
  for (int i = 0; i < 10; ++i) {
    EXPECT_NEAR(every_frame(i, i) / at_reference(i, i), 1.0 / 64.0, 1e-12) << i;
  }
  for (int i = 10; i < 14; ++i) EXPECT_EQ(every_frame(i, i), at_reference(i, i)) << i;
  EXPECT_GT(ekf.measurementNoise(0.0).diagonal().minCoeff(), 0.0);  // stays positive

  EkfConfig fixed = config;
  fixed.measurement_noise_interval_exponent = 0.0;  // the thesis: one R
  EXPECT_EQ(makeEkf(fixed).measurementNoise(kInterval / 4.0), at_reference);
}

TEST(EkfTest, ShorterIntervalsTrustTheExtrapolationMore) {
  const EkfConfig config;
  double pulled[2];
  const double intervals[2] = {kInterval / 4.0, kInterval};
  for (int i = 0; i < 2; ++i) {
    InitializationEkf ekf = makeEkf(config);
    ekf.start(identityQuat());
    ImuStep rest;
    rest.linear_acceleration = -kGravityMap;
    rest.dt = 0.005;
    for (int k = 0; k < 13; ++k) ekf.predict(rest);
    Vector14d measurement = ekf.state().toVector();
    measurement.segment<3>(7) = Eigen::Vector3d(0.01, 0.0, 0.0);
    ekf.correct(measurement, intervals[i]);
    pulled[i] = ekf.state().p.x() / 0.01;
  }
  EXPECT_GT(pulled[0], pulled[1]);
  EXPECT_GT(pulled[0], 0.0);
  EXPECT_LT(pulled[1], 1.0);
}

TEST(EkfTest, RejectsInvalidNoise) {
  EkfConfig config;
  config.process_noise_velocity = 0.0;
  EXPECT_THROW(config.validate(), std::invalid_argument);
  config = EkfConfig{};
  config.initial_covariance = std::nan("");
  EXPECT_THROW(config.validate(), std::invalid_argument);
  config = EkfConfig{};
  config.measurement_noise_reference_interval = 0.0;
  EXPECT_THROW(config.validate(), std::invalid_argument);
  config = EkfConfig{};
  config.measurement_noise_interval_exponent = -1.0;
  EXPECT_THROW(config.validate(), std::invalid_argument);
}

}  // namespace
