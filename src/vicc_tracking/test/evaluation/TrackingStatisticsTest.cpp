#include <gtest/gtest.h>

#include "vicc_tracking/tracking_statistics.hpp"

using namespace vicc_tracking;

namespace {

TEST(TrackingStatisticsTest, SummaryOfKnownSamples) {
  const SampleSummary summary = summarize({4.0, 1.0, 3.0, 2.0});
  EXPECT_EQ(summary.count, 4u);
  EXPECT_DOUBLE_EQ(summary.mean, 2.5);
  EXPECT_DOUBLE_EQ(summary.median, 2.5);
  EXPECT_NEAR(summary.stddev, std::sqrt(1.25), 1e-12);
  EXPECT_EQ(summarize({}).count, 0u);
}

TEST(TrackingStatisticsTest, CountsStatesAndSkipsStillFramesInRatios) {
  TrackingStatistics statistics;
  FrameReport report;
  report.state = TrackingState::kInitializing;
  statistics.add(report);
  report.accepted = false;
  statistics.add(report);
  report.accepted = true;
  report.state = TrackingState::kOk;
  report.identity_error_position = 1e-5;  // camera at rest: no ratio
  report.identity_error_rotation_deg = 0.01;
  statistics.add(report);
  report.icp.iterations = 5;
  report.identity_error_position = 0.02;
  report.init_error_position = 0.005;
  report.identity_error_rotation_deg = 4.0;
  report.init_error_rotation_deg = 1.0;
  report.camera_pose.translation() = Eigen::Vector3d(0.0, 0.03, 0.04);
  statistics.add(report);
  report.state = TrackingState::kLost;
  statistics.add(report);
  EXPECT_EQ(statistics.framesSeen(), 5);
  EXPECT_EQ(statistics.framesDropped(), 1);
  EXPECT_EQ(statistics.framesInitializing(), 1);
  EXPECT_EQ(statistics.framesTracked(), 2);
  EXPECT_EQ(statistics.framesLost(), 1);
  EXPECT_EQ(statistics.initRatioPosition().count, 1u);
  EXPECT_DOUBLE_EQ(statistics.initRatioPosition().mean, 0.25);
  EXPECT_DOUBLE_EQ(statistics.initRatioRotation().mean, 0.25);
  EXPECT_EQ(statistics.iterations().count, 1u);
  ASSERT_TRUE(statistics.loopClosureDrift().has_value());
  EXPECT_NEAR(statistics.loopClosureDrift()->translation, 0.05, 1e-12);
}

}  // namespace
