#include <gtest/gtest.h>

#include "vicc_tracking/ekf.hpp"
#include "vicc_tracking/sim/extrapolation_error.hpp"
#include "vicc_tracking/sim/scenario.hpp"

using namespace vicc_tracking;
using namespace vicc_tracking::sim;

namespace {

/// The extrapolation error of Eq. 5.13-5.15 on a fast scenario grows with the frame interval
/// as T^k with k between the EKF's default exponent (3) and the smooth-motion model's 4
/// (docs/imu_noise.md): the default R never trusts a shorter interval more than it deserves.
/// At every 4th frame the error is of the order of the default R.
TEST(ExtrapolationErrorTest, GrowsWithAPowerOfTheFrameIntervalAtLeastTheDefaultExponent) {
  const RigSimulator rig(loadScenario("hen"));
  std::vector<ExtrapolationError> errors;
  for (int step : {1, 2, 4}) errors.push_back(measureExtrapolationError(rig, step));
  for (size_t i = 1; i < errors.size(); ++i) {
    EXPECT_GT(errors[i].interval, errors[i - 1].interval);
    EXPECT_GT(errors[i].rotation, errors[i - 1].rotation);
    EXPECT_GT(errors[i].velocity, errors[i - 1].velocity);
    EXPECT_GT(errors[i].position, errors[i - 1].position);
  }
  const EkfConfig defaults;
  const IntervalExponents k = fitIntervalExponents(errors);
  for (const double exponent : {k.rotation, k.velocity, k.position}) {
    EXPECT_GE(exponent, defaults.measurement_noise_interval_exponent);
    EXPECT_LE(exponent, 4.5);
  }

  EXPECT_NEAR(errors.back().interval, defaults.measurement_noise_reference_interval, 1e-9);
  for (const double ratio : {errors.back().rotation / defaults.measurement_noise_rotation,
                             errors.back().velocity / defaults.measurement_noise_velocity,
                             errors.back().position / defaults.measurement_noise_position}) {
    EXPECT_GT(ratio, 0.1);
    EXPECT_LT(ratio, 10.0);
  }
}

TEST(ExtrapolationErrorTest, RejectsAStepWithTooFewFrames) {
  const RigSimulator rig(loadScenario("short_test"));
  EXPECT_THROW(measureExtrapolationError(rig, 0), std::invalid_argument);
  EXPECT_THROW(measureExtrapolationError(rig, 100000), std::invalid_argument);
  EXPECT_THROW(fitIntervalExponents({}), std::invalid_argument);
}

}  // namespace
