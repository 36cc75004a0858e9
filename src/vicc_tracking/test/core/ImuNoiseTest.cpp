#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "vicc_tracking/imu_noise.hpp"
#include "vicc_tracking/tracker_config_yaml.hpp"

using namespace vicc_tracking;

namespace {

const std::string kConfigDir = VICC_TRACKING_CONFIG_DIR;

/// The simulated rig's IMU (config/scenarios/*.yaml) in Kalibr's layout.
const char* const kSimulatedImu =
    "accelerometer_noise_density: 3.0e-3\n"
    "accelerometer_random_walk: 0.0\n"
    "gyroscope_noise_density: 3.0e-4\n"
    "gyroscope_random_walk: 0.0\n"
    "update_rate: 200.0\n"
    "rostopic: /imu/data_raw\n"
    "accelerometer_turn_on_bias: 0.031\n";

std::string errorOf(const std::string& yaml) {
  try {
    parseImuNoise(yaml, "imu.yaml");
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST(ImuNoiseTest, ReadsKalibrsLayout) {
  const ImuNoise noise = parseImuNoise(kSimulatedImu);
  EXPECT_EQ(noise.accelerometer_noise_density, 3.0e-3);
  EXPECT_EQ(noise.gyroscope_noise_density, 3.0e-4);
  EXPECT_EQ(noise.update_rate, 200.0);
  EXPECT_EQ(noise.rostopic, "/imu/data_raw");
  EXPECT_EQ(noise.accelerometer_turn_on_bias, 0.031);
  // A plain Kalibr file (no extension key) reads too.
  const ImuNoise kalibr = parseImuNoise(
      "accelerometer_noise_density: 1.86e-03\naccelerometer_random_walk: 4.33e-04\n"
      "gyroscope_noise_density: 1.87e-04\ngyroscope_random_walk: 2.66e-05\n"
      "rostopic: /imu0\nupdate_rate: 200.0\n");
  EXPECT_EQ(kalibr.accelerometer_random_walk, 4.33e-04);
  EXPECT_EQ(kalibr.accelerometer_turn_on_bias, 0.0);
}

TEST(ImuNoiseTest, ErrorsNameTheKey) {
  const std::string unknown = errorOf(std::string(kSimulatedImu) + "gyroscope_noise: 1.0\n");
  EXPECT_NE(unknown.find("imu.yaml: gyroscope_noise: unknown key"), std::string::npos) << unknown;
  const std::string type = errorOf("accelerometer_noise_density: loud\n");
  EXPECT_NE(type.find("accelerometer_noise_density: has the wrong type"), std::string::npos)
      << type;
  const std::string missing = errorOf("accelerometer_noise_density: 3.0e-3\nupdate_rate: 200\n");
  EXPECT_NE(missing.find("gyroscope_noise_density must be > 0"), std::string::npos) << missing;
  const std::string negative = errorOf(
      "accelerometer_noise_density: 3.0e-3\ngyroscope_noise_density: 3.0e-4\n"
      "update_rate: 200\naccelerometer_random_walk: -1.0\n");
  EXPECT_NE(negative.find("accelerometer_random_walk must be >= 0"), std::string::npos) << negative;
  EXPECT_THROW(loadImuNoise("/nonexistent/imu.yaml"), std::invalid_argument);
}

TEST(ImuNoiseTest, DerivedProcessNoiseFollowsTheDerivation) {
  const ImuNoise noise = parseImuNoise(kSimulatedImu);
  const EkfConfig base;
  const double still = 1.0;
  const EkfConfig derived = ekfNoiseFromImu(base, noise, still);
  const double dt = 1.0 / 200.0;
  const double interval = base.measurement_noise_reference_interval;
  // docs/imu_noise.md: Q_q = sigma_g^2 dt (1 + T / D) / 4 without bias walk.
  const double sigma_g2 = 3.0e-4 * 3.0e-4;
  EXPECT_NEAR(derived.process_noise_rotation, sigma_g2 * dt * (1.0 + interval / still) / 4.0,
              1e-18);
  EXPECT_EQ(derived.process_noise_base, derived.process_noise_rotation);
  // Q_v = sigma_a^2 dt (1 + T / D) + 4 (sqrt(3) b)^2 T dt.
  const double sigma_a2 = 3.0e-3 * 3.0e-3;
  const double offset = 3.0 * 0.031 * 0.031;
  EXPECT_NEAR(derived.process_noise_velocity,
              sigma_a2 * dt * (1.0 + interval / still) + 4.0 * offset * interval * dt, 1e-15);
  // The hand-tuned defaults (tracker.yaml) agree within a factor of two.
  EXPECT_GT(derived.process_noise_rotation / base.process_noise_rotation, 0.5);
  EXPECT_LT(derived.process_noise_rotation / base.process_noise_rotation, 2.0);
  EXPECT_GT(derived.process_noise_velocity / base.process_noise_velocity, 0.5);
  EXPECT_LT(derived.process_noise_velocity / base.process_noise_velocity, 2.0);
  // The accelerometer's share of Q_p is far below the Euler term: the configured value stays.
  EXPECT_EQ(derived.process_noise_position, base.process_noise_position);
  // R and P0 are not the IMU's.
  EXPECT_EQ(derived.measurement_noise_velocity, base.measurement_noise_velocity);
  EXPECT_EQ(derived.initial_covariance, base.initial_covariance);
  // Applying it twice changes nothing.
  const EkfConfig twice = ekfNoiseFromImu(derived, noise, still);
  EXPECT_EQ(twice.process_noise_rotation, derived.process_noise_rotation);
  EXPECT_EQ(twice.process_noise_velocity, derived.process_noise_velocity);
  EXPECT_EQ(twice.process_noise_position, derived.process_noise_position);
}

TEST(ImuNoiseTest, RandomWalkAndAnOffsetRaiseTheNoise) {
  ImuNoise noise = parseImuNoise(kSimulatedImu);
  const EkfConfig base;
  const EkfConfig without_walk = ekfNoiseFromImu(base, noise, 1.0);
  noise.gyroscope_random_walk = 1e-2;
  noise.accelerometer_random_walk = 1e-1;
  const EkfConfig with_walk = ekfNoiseFromImu(base, noise, 1.0);
  EXPECT_GT(with_walk.process_noise_rotation, without_walk.process_noise_rotation);
  EXPECT_GT(with_walk.process_noise_velocity, without_walk.process_noise_velocity);
  noise.accelerometer_turn_on_bias = 0.0;
  EXPECT_LT(ekfNoiseFromImu(base, noise, 1.0).process_noise_velocity,
            with_walk.process_noise_velocity);
  EXPECT_THROW(ekfNoiseFromImu(base, noise, 0.0), std::invalid_argument);
}

TEST(ImuNoiseTest, TrackerParameterFileSelectsTheImuFile) {
  const std::string path = kConfigDir + "/imu/simulated_rig.yaml";
  const TrackerParameterSet parameters =
      parseTrackerParameters("ekf:\n  imu_noise_file: " + path + "\n");
  const EkfConfig expected = ekfNoiseFromImu(EkfConfig{}, loadImuNoise(path), 1.0);
  EXPECT_EQ(parameters.tracker.ekf.imu_noise_file, path);
  EXPECT_EQ(parameters.tracker.ekf.process_noise_velocity, expected.process_noise_velocity);
  EXPECT_EQ(parameters.tracker.ekf.process_noise_rotation, expected.process_noise_rotation);
  // Written and read back: the same text (the derivation is idempotent).
  EXPECT_EQ(toYaml(parseTrackerParameters(toYaml(parameters))), toYaml(parameters));
  // A missing file is an error naming it.
  try {
    parseTrackerParameters("ekf:\n  imu_noise_file: /nonexistent/imu.yaml\n");
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent/imu.yaml"), std::string::npos);
  }
}

TEST(ImuNoiseTest, ShippedImuFilesLoad) {
  const ImuNoise simulated = loadImuNoise(kConfigDir + "/imu/simulated_rig.yaml");
  EXPECT_EQ(simulated.gyroscope_noise_density, 3.0e-4);
  const ImuNoise bmi270 = loadImuNoise(kConfigDir + "/imu/bosch_bmi270.yaml");
  EXPECT_NEAR(bmi270.accelerometer_noise_density, 160e-6 * 9.80665, 1e-6);
  EXPECT_NEAR(bmi270.gyroscope_noise_density, 0.007 * M_PI / 180.0, 1e-7);
  // A worse offset than the simulated IMU's: more velocity noise.
  EXPECT_GT(ekfNoiseFromImu(EkfConfig{}, bmi270, 1.0).process_noise_velocity,
            ekfNoiseFromImu(EkfConfig{}, simulated, 1.0).process_noise_velocity);
}

}  // namespace
