// The still phase (thesis 5.4.1): gyro bias and gravity as the means of the readings, when it
// is complete, and the warning when the rig was not still.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "vicc_tracking/still_phase.hpp"

using namespace vicc_tracking;

namespace {

const Eigen::Vector3d kGyroBias(0.01, -0.02, 0.005);
const Eigen::Vector3d kGravity(0.3, -0.2, 9.79);  // tilted rig plus accelerometer bias

/// Reading k of a still rig at `rate_hz`: bias and gravity plus a symmetric +-`wiggle`
/// alternation (mean zero over an even count, standard deviation `wiggle`).
ImuSample stillReading(int k, double rate_hz, double gyro_wiggle = 1e-3,
                       double accel_wiggle = 1e-2) {
  const double sign = k % 2 == 0 ? 1.0 : -1.0;
  ImuSample sample;
  sample.stamp = 100.0 + k / rate_hz;
  sample.angular_velocity = kGyroBias + sign * gyro_wiggle * Eigen::Vector3d::Ones();
  sample.linear_acceleration = kGravity + sign * accel_wiggle * Eigen::Vector3d::Ones();
  return sample;
}

TEST(StillPhaseTest, CalibrationIsTheMeanOfTheStillReadings) {
  StillPhaseCalibrator calibrator{StillPhaseConfig{}};
  for (int k = 0; k < 400; ++k) calibrator.add(stillReading(k, 200.0));
  ASSERT_TRUE(calibrator.complete());
  const ImuCalibration calibration = calibrator.calibration();
  EXPECT_NEAR((calibration.gyro_bias - kGyroBias).norm(), 0.0, 1e-12);
  EXPECT_NEAR((calibration.gravity_imu - kGravity).norm(), 0.0, 1e-12);
  EXPECT_EQ(calibrator.motionWarning(), "");
}

TEST(StillPhaseTest, CompleteNeedsTheDurationAndTenReadings) {
  StillPhaseConfig config;
  config.duration = 0.5;
  StillPhaseCalibrator calibrator(config);
  for (int k = 0; k < 100; ++k) {  // 0.495 s of readings at 200 Hz
    calibrator.add(stillReading(k, 200.0));
    EXPECT_FALSE(calibrator.complete()) << k;
  }
  calibrator.add(stillReading(100, 200.0));  // 0.5 s after the first
  EXPECT_TRUE(calibrator.complete());

  StillPhaseCalibrator sparse(config);  // 2 Hz: the duration passes with too few readings
  for (int k = 0; k < 9; ++k) sparse.add(stillReading(k, 2.0));
  EXPECT_FALSE(sparse.complete());
  sparse.add(stillReading(9, 2.0));
  EXPECT_TRUE(sparse.complete());
}

TEST(StillPhaseTest, WarnsWhenTheRigTurnedOrShook) {
  StillPhaseCalibrator turning{StillPhaseConfig{}};  // max_gyro_std 0.05 rad/s
  for (int k = 0; k < 400; ++k) turning.add(stillReading(k, 200.0, 0.2));
  const std::string gyro_warning = turning.motionWarning();
  EXPECT_NE(gyro_warning.find("not still"), std::string::npos) << gyro_warning;
  EXPECT_NE(gyro_warning.find("gyro std 0.2"), std::string::npos) << gyro_warning;
  EXPECT_EQ(gyro_warning.find("accelerometer"), std::string::npos) << gyro_warning;

  StillPhaseCalibrator shaking{StillPhaseConfig{}};  // max_accel_std 0.5 m/s^2
  for (int k = 0; k < 400; ++k) shaking.add(stillReading(k, 200.0, 1e-3, 2.0));
  const std::string accel_warning = shaking.motionWarning();
  EXPECT_NE(accel_warning.find("accelerometer std 2"), std::string::npos) << accel_warning;
  EXPECT_EQ(accel_warning.find("gyro"), std::string::npos) << accel_warning;

  // Just below the limits: no warning.
  StillPhaseCalibrator calm{StillPhaseConfig{}};
  for (int k = 0; k < 400; ++k) calm.add(stillReading(k, 200.0, 0.049, 0.49));
  EXPECT_EQ(calm.motionWarning(), "");
}

TEST(StillPhaseTest, WarnsWhenTheMeanSpecificForceIsNotGravity) {
  StillPhaseCalibrator falling{StillPhaseConfig{}};
  for (int k = 0; k < 400; ++k) {
    ImuSample sample = stillReading(k, 200.0);
    sample.linear_acceleration *= 0.5;  // ~4.9 m/s^2: accelerating, or a wrong unit
    falling.add(sample);
  }
  EXPECT_NE(falling.motionWarning().find("far from gravity"), std::string::npos)
      << falling.motionWarning();
}

TEST(StillPhaseTest, NonFiniteAndOutOfOrderReadingsAreIgnored) {
  StillPhaseCalibrator calibrator{StillPhaseConfig{}};
  for (int k = 0; k < 400; ++k) {
    calibrator.add(stillReading(k, 200.0));
    ImuSample nan_reading = stillReading(k, 200.0);
    nan_reading.stamp += 1e-4;
    nan_reading.angular_velocity.x() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(calibrator.add(nan_reading));
    ImuSample infinite = stillReading(k, 200.0);
    infinite.stamp += 2e-4;
    infinite.linear_acceleration.z() = std::numeric_limits<double>::infinity();
    EXPECT_FALSE(calibrator.add(infinite));
    ImuSample late = stillReading(k, 200.0);
    late.stamp -= 1.0;  // older than the readings already averaged
    late.angular_velocity *= 100.0;
    EXPECT_FALSE(calibrator.add(late));
  }
  ASSERT_TRUE(calibrator.complete());
  EXPECT_NEAR((calibrator.calibration().gyro_bias - kGyroBias).norm(), 0.0, 1e-12);
  EXPECT_NEAR((calibrator.calibration().gravity_imu - kGravity).norm(), 0.0, 1e-12);
  EXPECT_EQ(calibrator.motionWarning(), "");
}

TEST(StillPhaseTest, EmptyAndResetCalibratorsGiveTheDefaults) {
  StillPhaseCalibrator calibrator{StillPhaseConfig{}};
  const ImuCalibration defaults;
  EXPECT_FALSE(calibrator.complete());
  EXPECT_EQ(calibrator.calibration().gyro_bias, defaults.gyro_bias);
  EXPECT_EQ(calibrator.calibration().gravity_imu, defaults.gravity_imu);
  EXPECT_EQ(calibrator.motionWarning(), "");

  for (int k = 0; k < 400; ++k) calibrator.add(stillReading(k, 200.0, 0.2));
  ASSERT_TRUE(calibrator.complete());
  calibrator.reset();
  EXPECT_FALSE(calibrator.complete());
  EXPECT_EQ(calibrator.calibration().gravity_imu, defaults.gravity_imu);
  EXPECT_EQ(calibrator.motionWarning(), "");
  EXPECT_TRUE(calibrator.add(stillReading(0, 200.0)));  // an earlier stamp starts afresh
}

TEST(StillPhaseTest, RejectsInvalidConfiguration) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double StillPhaseConfig::*field :
       {&StillPhaseConfig::duration, &StillPhaseConfig::max_gyro_std,
        &StillPhaseConfig::max_accel_std}) {
    for (const double bad : {0.0, -1.0, nan}) {
      StillPhaseConfig config;
      config.*field = bad;
      EXPECT_THROW(StillPhaseCalibrator{config}, std::invalid_argument);
    }
  }
  StillPhaseConfig endless;
  endless.duration = std::numeric_limits<double>::infinity();
  EXPECT_THROW(StillPhaseCalibrator{endless}, std::invalid_argument);
}

}  // namespace
