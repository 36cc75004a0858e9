#include <gtest/gtest.h>

#include <cmath>

#include "vicc_tracking/ekf.hpp"
#include "vicc_tracking/init_strategy.hpp"

using namespace vicc_tracking;

namespace {

const Eigen::Vector3d kGravity(0.0, 0.0, 9.80665);

/// Analytic motion: constant body angular velocity and constant map-frame acceleration.
struct AnalyticMotion {
  Eigen::Quaterniond start_orientation;
  Eigen::Vector3d body_rate;
  Eigen::Vector3d start_velocity;
  Eigen::Vector3d acceleration;

  Eigen::Quaterniond orientation(double t) const {
    const double angle = body_rate.norm() * t;
    return start_orientation * Eigen::Quaterniond(Eigen::AngleAxisd(angle, body_rate.normalized()));
  }
  Eigen::Vector3d position(double t) const {
    return start_velocity * t + 0.5 * acceleration * t * t;
  }
  /// Noise-free REP-145 reading at t: body rate and specific force in the body frame.
  ImuStep reading(double t, double dt) const {
    ImuStep step;
    step.angular_velocity = body_rate;
    step.linear_acceleration = orientation(t).inverse() * (acceleration + kGravity);
    step.dt = dt;
    return step;
  }
};

Vector14d numericalStep(const InitializationEkf& ekf, const ImuStep& step) {
  InitializationEkf copy = ekf;
  copy.predict(step);
  return copy.state().toVector();
}

}  // namespace

TEST(EkfTest, PredictionWithNoiseFreeImuReproducesTrueRelativePose) {
  AnalyticMotion motion{Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized())),
                        Eigen::Vector3d(0.8, -1.2, 0.5), Eigen::Vector3d(0.3, -0.2, 0.1),
                        Eigen::Vector3d(1.5, 0.5, -2.0)};
  InitializationEkf ekf(EkfConfig{}, ImuCalibration{}, kGravity);
  ekf.start(toQuat4(motion.start_orientation));
  // The EKF starts each interval with the velocity carried over from the last one.
  InitializationEkf::State* unused = nullptr;
  (void)unused;
}
