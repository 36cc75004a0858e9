// The tracking/fusion hand-over: an empty model grows from tracked frames until its prediction
// takes over as the ICP reference; untracked frames are not fused; a restart starts a new model.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>

#include "synthetic_frames.hpp"
#include "vicc_fusion/frame_to_model.hpp"
#include "vicc_tracking/sim/rig_simulator.hpp"

namespace vicc_fusion {
namespace {

using vicc_tracking::FrameReport;
using vicc_tracking::TrackingState;

// Frames 30.. of short_test lie after its still phase: the camera moves.
constexpr int kFirst = 30;
// Frames within which the model must be stable enough to replace the last frame (the stable
// confidence of 3 needs at least 3 observations at the image centre).
constexpr int kTakeOverWithin = 12;

class FrameToModelTest : public ::testing::Test {
 protected:
  FrameToModelTest() : rig_(vicc_tracking::sim::loadScenario("short_test")) {
    vicc_tracking::TrackerConfig config;
    config.init_strategy = vicc_tracking::InitStrategyType::kIdentity;
    config.wait_for_imu = false;  // depth only: the map starts at the first frame
    tracker_ = std::make_unique<vicc_tracking::Tracker>(config, rig_.scenario().imu_to_camera);
    tracker_->setCamera(rig_.scenario().camera);
  }

  FrameReport track(int k) { return tracker_->addDepth(rig_.depthTimes()[k], rig_.renderDepth(k)); }

  vicc_tracking::sim::RigSimulator rig_;
  std::unique_ptr<vicc_tracking::Tracker> tracker_;
};

TEST_F(FrameToModelTest, AnEmptyModelGrowsUntilItsPredictionTakesOverTracking) {
  FrameToModel model{FrameToModelConfig{}};
  ASSERT_TRUE(model.fusion().surfels().empty());

  const FrameReport first = track(kFirst);
  ASSERT_EQ(first.state, TrackingState::kOk);
  const FrameToModelStep start = model.afterFrame(*tracker_, first);
  EXPECT_TRUE(start.fused);
  EXPECT_GT(start.fusion.added, 1000);
  EXPECT_EQ(model.fusion().surfels().size(), static_cast<size_t>(start.fusion.added));
  EXPECT_EQ(model.fusion().stableCount(), 0u);  // one observation is not yet stable
  EXPECT_FALSE(start.prediction_used);
  EXPECT_EQ(start.prediction_coverage, 0.0);

  int take_over = -1;
  for (int k = kFirst + 1; k <= kFirst + kTakeOverWithin && take_over < 0; ++k) {
    const FrameReport report = track(k);
    ASSERT_EQ(report.state, TrackingState::kOk) << report.message;
    EXPECT_FALSE(report.aligned_to_model);  // no prediction was handed over yet
    const FrameToModelStep step = model.afterFrame(*tracker_, report);
    EXPECT_TRUE(step.fused);
    EXPECT_GE(step.prediction_coverage, 0.0);
    EXPECT_LE(step.prediction_coverage, 1.0);
    EXPECT_EQ(step.prediction_used,
              step.prediction_coverage >= model.config().min_prediction_coverage);
    if (step.prediction_used) take_over = k;
  }
  ASSERT_GE(take_over, 0) << "the model never covered half of the view";
  EXPECT_GT(model.fusion().stableCount(), 1000u);

  const FrameReport aligned = track(take_over + 1);
  EXPECT_EQ(aligned.state, TrackingState::kOk) << aligned.message;
  EXPECT_TRUE(aligned.aligned_to_model);
  EXPECT_FALSE(aligned.model_fallback);
  const Eigen::Isometry3d truth = rig_.cameraPose(rig_.depthTimes()[kFirst]).inverse() *
                                  rig_.cameraPose(rig_.depthTimes()[take_over + 1]);
  const Eigen::Isometry3d estimate = first.camera_pose.inverse() * aligned.camera_pose;
  EXPECT_LT((truth.translation() - estimate.translation()).norm(), 0.003);
}

TEST_F(FrameToModelTest, FramesThatWereNotTrackedAreNotFused) {
  FrameToModel model{FrameToModelConfig{}};
  FrameReport report = track(kFirst);
  ASSERT_EQ(report.state, TrackingState::kOk);
  model.afterFrame(*tracker_, report);
  const size_t surfels = model.fusion().surfels().size();

  FrameReport dropped = report;
  dropped.accepted = false;
  FrameReport lost = report;
  lost.state = TrackingState::kLost;
  FrameReport initializing = report;
  initializing.state = TrackingState::kInitializing;
  for (const FrameReport& untracked : {dropped, lost, initializing}) {
    const FrameToModelStep step = model.afterFrame(*tracker_, untracked);
    EXPECT_FALSE(step.fused);
    EXPECT_FALSE(step.prediction_used);
    EXPECT_EQ(step.fusion.added, 0);
  }
  EXPECT_EQ(model.fusion().surfels().size(), surfels);
  EXPECT_EQ(model.fusion().framesIntegrated(), 1);
}

TEST_F(FrameToModelTest, ARestartOfTrackingStartsANewModel) {
  FrameToModel model{FrameToModelConfig{}};
  for (int k = kFirst; k < kFirst + 4; ++k) model.afterFrame(*tracker_, track(k));
  ASSERT_EQ(model.fusion().framesIntegrated(), 4);

  tracker_->reset();  // e.g. a clock jump: the next frame is frame 0 of a new map
  const FrameReport restart = track(kFirst + 10);
  ASSERT_EQ(restart.frame_index, 0);
  const FrameToModelStep step = model.afterFrame(*tracker_, restart);
  EXPECT_TRUE(step.fused);
  EXPECT_EQ(model.fusion().framesIntegrated(), 1);
  EXPECT_EQ(model.fusion().surfels().size(), static_cast<size_t>(step.fusion.added));
}

TEST_F(FrameToModelTest, FuseOnlyNeverHandsAPredictionToTheTracker) {
  FrameToModelConfig config;
  config.track_against_model = false;
  FrameToModel model(config);
  for (int k = kFirst; k <= kFirst + kTakeOverWithin; ++k) {
    const FrameReport report = track(k);
    ASSERT_EQ(report.state, TrackingState::kOk) << report.message;
    EXPECT_FALSE(report.aligned_to_model);
    const FrameToModelStep step = model.afterFrame(*tracker_, report);
    EXPECT_TRUE(step.fused);
    EXPECT_FALSE(step.prediction_used);
  }
  EXPECT_GT(model.fusion().stableCount(), 1000u);  // the model was built all the same
}

TEST(FrameToModelFuseTest, FusesAFrameAtTheGivenPoseInTheMapFrame) {
  FrameToModel model{FrameToModelConfig{}};
  Eigen::Isometry3d camera_pose = Eigen::Isometry3d::Identity();
  camera_pose.translation() = Eigen::Vector3d(0.1, -0.2, 0.3);
  const FrameToModelStep step = model.fuse(test::planeFrame(0.6, 0.0, 1), camera_pose);
  EXPECT_TRUE(step.fused);
  EXPECT_FALSE(step.prediction_used);
  ASSERT_EQ(model.fusion().surfels().size(), 64u * 48u);
  for (const Surfel& surfel : model.fusion().surfels()) {
    ASSERT_NEAR(surfel.position.z(), 0.9f, 1e-5f);  // 0.6 m in front of a camera at z = 0.3
    ASSERT_NEAR(surfel.normal.z(), -1.f, 1e-5f);
  }
}

TEST(FrameToModelFuseTest, NewThresholdsApplyToTheNextFrameAndInvalidOnesChangeNothing) {
  FrameToModel model{FrameToModelConfig{}};
  model.fuse(test::planeFrame(0.6, 0.0, 1), Eigen::Isometry3d::Identity());
  const size_t surfels = model.fusion().surfels().size();
  ASSERT_GT(surfels, 0u);

  SurfelFusionConfig near_only = model.config().fusion;
  near_only.max_view_distance = 0.5;  // the plane at 0.6 m is out of reach now
  near_only.stable_confidence = 5.0;
  model.setFusionConfig(near_only);
  EXPECT_EQ(model.fusion().config().max_view_distance, 0.5);
  EXPECT_EQ(model.config().prediction.stable_confidence, 5.0);
  const FrameToModelStep step =
      model.fuse(test::planeFrame(0.6, 0.0, 2), Eigen::Isometry3d::Identity());
  EXPECT_EQ(step.fusion.added + step.fusion.merged + step.fusion.confirmed, 0);
  EXPECT_EQ(model.fusion().surfels().size(), surfels);  // the model is kept

  SurfelFusionConfig invalid = near_only;
  invalid.max_normal_angle_deg = 95.0;
  EXPECT_THROW(model.setFusionConfig(invalid), std::invalid_argument);
  EXPECT_EQ(model.fusion().config().max_normal_angle_deg, 20.0);
  EXPECT_EQ(model.config().fusion.max_normal_angle_deg, 20.0);
}

TEST(FrameToModelConfigTest, RejectsACoverageOutsideTheUnitIntervalAndSharesStability) {
  for (const double coverage : {-0.1, 1.1, std::numeric_limits<double>::quiet_NaN()}) {
    FrameToModelConfig config;
    config.min_prediction_coverage = coverage;
    EXPECT_THROW(FrameToModel{config}, std::invalid_argument) << coverage;
  }
  FrameToModelConfig config;
  config.fusion.stable_confidence = 5.0;
  config.prediction.stable_confidence = 1.0;  // overridden: the tracker aligns to the stable model
  EXPECT_EQ(FrameToModel(config).config().prediction.stable_confidence, 5.0);
}

}  // namespace
}  // namespace vicc_fusion
