// The Tracker on simulated frames: frame-to-frame, and the frame-to-model hand-over with its
// fallback to the previous frame.
#include <gtest/gtest.h>

#include "vicc_tracking/sim/rig_simulator.hpp"
#include "vicc_tracking/tracker.hpp"

using namespace vicc_tracking;

namespace {

class TrackerTest : public ::testing::Test {
 protected:
  TrackerTest() : rig_(sim::loadScenario("short_test")) {
    TrackerConfig config;
    config.init_strategy = InitStrategyType::kIdentity;
    config.wait_for_imu = false;  // depth only: the map starts at the first frame
    tracker_ = std::make_unique<Tracker>(config, rig_.scenario().imu_to_camera);
    tracker_->setCamera(rig_.scenario().camera);
  }

  /// Tracks frame k; returns the report.
  FrameReport track(int k) { return tracker_->addDepth(rig_.depthTimes()[k], rig_.renderDepth(k)); }

  /// Tracked pose vs ground truth, both relative to frame `first`.
  double positionError(const FrameReport& report, const FrameReport& first, int k, int k0) {
    const Eigen::Isometry3d truth =
        rig_.cameraPose(rig_.depthTimes()[k0]).inverse() * rig_.cameraPose(rig_.depthTimes()[k]);
    const Eigen::Isometry3d estimate = first.camera_pose.inverse() * report.camera_pose;
    return (truth.translation() - estimate.translation()).norm();
  }

  sim::RigSimulator rig_;
  std::unique_ptr<Tracker> tracker_;
};

// Frames 30.. lie after the still phase of short_test: the camera moves.
constexpr int kFirst = 30;

TEST_F(TrackerTest, FollowsTheSimulatedCameraFrameToFrame) {
  const FrameReport first = track(kFirst);
  ASSERT_EQ(first.state, TrackingState::kOk);
  FrameReport report;
  for (int k = kFirst + 1; k < kFirst + 15; ++k) {
    report = track(k);
    ASSERT_EQ(report.state, TrackingState::kOk) << report.message;
    EXPECT_FALSE(report.aligned_to_model);
  }
  EXPECT_LT(positionError(report, first, kFirst + 14, kFirst), 0.005);
}

TEST_F(TrackerTest, FallsBackToTheLastFrameWhenTheModelPredictionMisleads) {
  const FrameReport first = track(kFirst);
  ASSERT_EQ(first.state, TrackingState::kOk);
  // A "prediction" that is the current frame 0.5 m too far away: ICP against it cannot find
  // correspondences, so the tracker must align to the frame itself.
  DepthPyramid misleading = tracker_->currentFrame();
  for (DepthLevel& level : misleading) {
    for (Eigen::Vector3f& vertex : level.vertices) {
      if (vertex.z() > 0.f) vertex.z() += 0.5f;
    }
  }
  ASSERT_TRUE(tracker_->useModelPrediction(std::move(misleading)));
  const FrameReport report = track(kFirst + 1);
  EXPECT_EQ(report.state, TrackingState::kOk) << report.message;
  EXPECT_TRUE(report.model_fallback);
  EXPECT_FALSE(report.aligned_to_model);
  EXPECT_LT(positionError(report, first, kFirst + 1, kFirst), 0.003);
}

TEST_F(TrackerTest, UsesAGoodPredictionAndRejectsAWrongLayout) {
  track(kFirst);
  DepthPyramid same = tracker_->currentFrame();  // a perfect "model": the frame itself
  ASSERT_TRUE(tracker_->useModelPrediction(std::move(same)));
  const FrameReport report = track(kFirst + 1);
  EXPECT_TRUE(report.aligned_to_model);
  EXPECT_FALSE(report.model_fallback);

  DepthPyramid truncated = tracker_->currentFrame();
  truncated.pop_back();
  EXPECT_FALSE(tracker_->useModelPrediction(std::move(truncated)));
  EXPECT_FALSE(track(kFirst + 2).aligned_to_model);
}

}  // namespace
