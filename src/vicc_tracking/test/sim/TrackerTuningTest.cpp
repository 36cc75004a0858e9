// Tuning a running tracker (what dynamic_reconfigure calls): a valid ICP or EKF config applies
// from the next frame on, an invalid one throws and changes nothing.
#include <gtest/gtest.h>

#include "vicc_tracking/ekf.hpp"
#include "vicc_tracking/sim/rig_simulator.hpp"
#include "vicc_tracking/tracker.hpp"

using namespace vicc_tracking;

namespace {

// Frames 30.. lie after the still phase of short_test: the camera moves.
constexpr int kFirst = 30;

class TrackerTuningTest : public ::testing::Test {
 protected:
  TrackerTuningTest() : rig_(sim::loadScenario("short_test")) {
    TrackerConfig config;
    config.init_strategy = InitStrategyType::kIdentity;
    config.wait_for_imu = false;
    tracker_ = std::make_unique<Tracker>(config, rig_.scenario().imu_to_camera);
    tracker_->setCamera(rig_.scenario().camera);
  }
  FrameReport track(int k) { return tracker_->addDepth(rig_.depthTimes()[k], rig_.renderDepth(k)); }

  sim::RigSimulator rig_;
  std::unique_ptr<Tracker> tracker_;
};

TEST_F(TrackerTuningTest, AnIcpChangeAppliesFromTheNextFrame) {
  ASSERT_EQ(track(kFirst).state, TrackingState::kOk);
  ASSERT_EQ(track(kFirst + 1).state, TrackingState::kOk);

  IcpConfig strict = tracker_->config().icp;
  strict.min_inliers = 10000000;  // more than the frame has pixels
  tracker_->setIcpConfig(strict);
  EXPECT_EQ(tracker_->config().icp.min_inliers, 10000000);
  const FrameReport failing = track(kFirst + 2);
  EXPECT_EQ(failing.state, TrackingState::kLost);
  EXPECT_NE(failing.message.find("too few correspondences"), std::string::npos) << failing.message;

  strict.min_inliers = 200;
  tracker_->setIcpConfig(strict);
  EXPECT_EQ(track(kFirst + 3).state, TrackingState::kOk);
}

TEST_F(TrackerTuningTest, AnInvalidChangeThrowsAndKeepsTheOldValues) {
  ASSERT_EQ(track(kFirst).state, TrackingState::kOk);
  IcpConfig bad_icp = tracker_->config().icp;
  bad_icp.min_inliers = 3;
  EXPECT_THROW(tracker_->setIcpConfig(bad_icp), std::invalid_argument);
  EXPECT_EQ(tracker_->config().icp.min_inliers, 200);

  EkfConfig bad_ekf = tracker_->config().ekf;
  bad_ekf.measurement_noise_velocity = -1.0;
  EXPECT_THROW(tracker_->setEkfConfig(bad_ekf), std::invalid_argument);
  EXPECT_EQ(tracker_->config().ekf.measurement_noise_velocity,
            EkfConfig{}.measurement_noise_velocity);
  EXPECT_EQ(track(kFirst + 1).state, TrackingState::kOk);
}

TEST(EkfTuningTest, NewNoiseAppliesToTheRunningFilterAndInvalidIsRefused) {
  InitializationEkf ekf(EkfConfig{}, ImuCalibration{}, Eigen::Vector3d(0.0, 0.0, 9.80665));
  const double interval = EkfConfig{}.measurement_noise_reference_interval;
  const int velocity = 4;  // state index of v_x: [q(4) v(3) p(3) q_b(4)]
  EXPECT_DOUBLE_EQ(ekf.measurementNoise(interval)(velocity, velocity), 0.2);

  EkfConfig tuned;
  tuned.measurement_noise_velocity = 0.5;
  tuned.measurement_noise_interval_exponent = 0.0;  // one fixed R
  ekf.setConfig(tuned);
  EXPECT_DOUBLE_EQ(ekf.measurementNoise(interval)(velocity, velocity), 0.5);
  EXPECT_DOUBLE_EQ(ekf.measurementNoise(4.0 * interval)(velocity, velocity), 0.5);

  EkfConfig invalid = tuned;
  invalid.measurement_noise_interval_exponent = 9.0;  // beyond [0, 8]
  EXPECT_THROW(ekf.setConfig(invalid), std::invalid_argument);
  EXPECT_DOUBLE_EQ(ekf.measurementNoise(4.0 * interval)(velocity, velocity), 0.5);
}

}  // namespace
