// The dynamic_reconfigure side of the fusion thresholds: the .cfg defaults are
// SurfelFusionConfig's, the table-driven conversions carry every field both ways and keep the
// start-up ones.
#include <gtest/gtest.h>

#include "vicc_fusion/ros/fusion_reconfigure.hpp"

namespace vicc_fusion {
namespace {

TEST(FusionReconfigureTest, CfgDefaultsAreTheConfigDefaults) {
  const SurfelFusionConfig fusion =
      vicc_tracking::fromTuning(FusionTuningConfig::__getDefault__(), SurfelFusionConfig{});
  const SurfelFusionConfig expected;
  EXPECT_EQ(fusion.max_depth_difference, expected.max_depth_difference);
  EXPECT_EQ(fusion.max_normal_angle_deg, expected.max_normal_angle_deg);
  EXPECT_EQ(fusion.max_radius_growth, expected.max_radius_growth);
  EXPECT_EQ(fusion.confidence_sigma, expected.confidence_sigma);
  EXPECT_EQ(fusion.stable_confidence, expected.stable_confidence);
  EXPECT_EQ(fusion.unstable_lifetime, expected.unstable_lifetime);
  EXPECT_EQ(fusion.free_space_margin, expected.free_space_margin);
  EXPECT_EQ(fusion.max_view_distance, expected.max_view_distance);
}

TEST(FusionReconfigureTest, ConversionsCarryEveryFieldAndKeepTheStartUpOnes) {
  SurfelFusionConfig tuned;
  tuned.max_depth_difference = 0.02;
  tuned.max_normal_angle_deg = 25.0;
  tuned.max_radius_growth = 0.7;
  tuned.confidence_sigma = 0.6;
  tuned.stable_confidence = 5.0;
  tuned.unstable_lifetime = 30;
  tuned.free_space_margin = 0.05;
  tuned.max_view_distance = 2.5;
  SurfelFusionConfig base;
  base.supersampling = 2;
  base.max_surfels = 1234;
  base.sort_interval = 0;
  const SurfelFusionConfig back =
      vicc_tracking::fromTuning(vicc_tracking::toTuning<FusionTuningConfig>(tuned), base);
  EXPECT_EQ(back.max_depth_difference, 0.02);
  EXPECT_EQ(back.max_normal_angle_deg, 25.0);
  EXPECT_EQ(back.max_radius_growth, 0.7);
  EXPECT_EQ(back.confidence_sigma, 0.6);
  EXPECT_EQ(back.stable_confidence, 5.0);
  EXPECT_EQ(back.unstable_lifetime, 30);
  EXPECT_EQ(back.free_space_margin, 0.05);
  EXPECT_EQ(back.max_view_distance, 2.5);
  EXPECT_EQ(back.supersampling, 2);
  EXPECT_EQ(back.max_surfels, 1234);
  EXPECT_EQ(back.sort_interval, 0);
}

}  // namespace
}  // namespace vicc_fusion
