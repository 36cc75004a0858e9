#include <gtest/gtest.h>

#include <cmath>

#include "synthetic_frames.hpp"
#include "vicc_fusion/surfel_fusion.hpp"

namespace vicc_fusion {
namespace {

using test::planeFrame;
using test::smallCamera;
using test::syntheticFrame;

/// Standard deviation of the surfels' z around `depth` (mean is checked separately).
std::pair<double, double> zMeanAndStd(const SurfelVector& surfels) {
  double sum = 0.0, sum_squared = 0.0;
  for (const Surfel& s : surfels) {
    sum += s.position.z();
    sum_squared += s.position.z() * s.position.z();
  }
  const double mean = sum / surfels.size();
  return {mean, std::sqrt(std::max(0.0, sum_squared / surfels.size() - mean * mean))};
}

Eigen::Isometry3d shifted(double x, double y) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(x, y, 0.0);
  return pose;
}

TEST(SurfelFusionTest, MergingNoisyViewsOfAPlaneLowersTheNoise) {
  SurfelFusion fusion{SurfelFusionConfig{}};
  const double sigma = 0.002;
  fusion.integrate(planeFrame(0.6, sigma, 1), Eigen::Isometry3d::Identity());
  const size_t single_view_count = fusion.surfels().size();
  const auto [mean1, std1] = zMeanAndStd(fusion.surfels());
  EXPECT_NEAR(std1, sigma, 0.2 * sigma);

  for (unsigned view = 2; view <= 9; ++view) {
    // Small hand-held jitter: the same plane from slightly different places.
    fusion.integrate(planeFrame(0.6, sigma, view), shifted(0.002 * (view % 3), 0.001 * (view % 2)));
  }
  // Restrict to the surfels every view saw (the border grows a little with the shifts).
  SurfelVector merged;
  for (const Surfel& s : fusion.surfels()) {
    if (s.confidence > 3.0f && fusion.isStable(s)) merged.push_back(s);
  }
  ASSERT_GT(merged.size(), single_view_count / 2);
  const auto [mean9, std9] = zMeanAndStd(merged);
  EXPECT_NEAR(mean9, 0.6, 0.0005);
  EXPECT_LT(std9, 0.55 * std1) << "nine merged views should average the noise down";
  // Views of the same surface merge instead of piling up new surfels.
  EXPECT_LT(fusion.surfels().size(), 1.3 * single_view_count);
}

TEST(SurfelFusionTest, MeasurementsNearTheImageCentreWeighMore) {
  const SurfelFusionConfig config;
  SurfelFusion fusion(config);
  fusion.integrate(planeFrame(0.6, 0.0, 1), Eigen::Isometry3d::Identity());
  float centre = 0.f, corner = 2.f;
  for (const Surfel& s : fusion.surfels()) {
    const float lateral = std::hypot(s.position.x(), s.position.y());
    if (lateral < 0.01f) centre = std::max(centre, s.confidence);
    if (lateral > 0.3f) corner = std::min(corner, s.confidence);
  }
  EXPECT_NEAR(centre, 1.0f, 0.02f);
  // The image corner is at normalised radial distance 1: weight exp(-1 / (2 sigma^2)).
  const double sigma = config.confidence_sigma;
  EXPECT_NEAR(corner, std::exp(-1.0 / (2.0 * sigma * sigma)), 0.03);
}

TEST(SurfelFusionTest, UnconfirmedOutliersVanishAfterTheirLifetime) {
  SurfelFusionConfig config;
  config.unstable_lifetime = 5;
  SurfelFusion fusion(config);
  // Frame 0: the plane plus a block of outliers 30 cm behind it (flying pixels).
  const auto with_outliers = syntheticFrame(
      smallCamera(),
      [](int u, int v) { return (u > 20 && u < 26 && v > 20 && v < 26) ? 0.9 : 0.6; }, 0.001, 1);
  fusion.integrate(with_outliers, Eigen::Isometry3d::Identity());
  auto outliers = [&fusion] {
    int count = 0;
    for (const Surfel& s : fusion.surfels()) count += s.position.z() > 0.8f;
    return count;
  };
  ASSERT_EQ(outliers(), 25);
  for (int frame = 1; frame <= config.unstable_lifetime; ++frame) {
    fusion.integrate(planeFrame(0.6, 0.001, 10 + frame), Eigen::Isometry3d::Identity());
  }
  EXPECT_EQ(outliers(), 25) << "still within their lifetime";
  fusion.integrate(planeFrame(0.6, 0.001, 99), Eigen::Isometry3d::Identity());
  EXPECT_EQ(outliers(), 0);
  EXPECT_GT(fusion.stableCount(), 0.5 * smallCamera().width * smallCamera().height);
}

TEST(SurfelFusionTest, SeeingThroughASurfelRemovesIt) {
  SurfelFusion fusion{SurfelFusionConfig{}};
  // An object 20 cm in front of the wall, observed long enough to become stable ...
  auto with_object = [](int u, int v) {
    return (u >= 28 && u < 36 && v >= 20 && v < 28) ? 0.4 : 0.6;
  };
  for (unsigned frame = 0; frame < 8; ++frame) {
    fusion.integrate(syntheticFrame(smallCamera(), with_object, 0.0005, frame),
                     Eigen::Isometry3d::Identity());
  }
  auto object_surfels = [&fusion] {
    int count = 0;
    for (const Surfel& s : fusion.surfels()) count += s.position.z() < 0.5f;
    return count;
  };
  ASSERT_EQ(object_surfels(), 64);
  // ... then it is gone: the camera sees the wall where it stood.
  const FusionFrameStats first =
      fusion.integrate(planeFrame(0.6, 0.0005, 50), Eigen::Isometry3d::Identity());
  EXPECT_GT(object_surfels(), 0) << "one contradiction does not erase a well-observed surface";
  int removed = first.removed_free_space;
  for (unsigned frame = 51; frame < 56; ++frame) {
    removed += fusion.integrate(planeFrame(0.6, 0.0005, frame), Eigen::Isometry3d::Identity())
                   .removed_free_space;
  }
  EXPECT_EQ(object_surfels(), 0);
  EXPECT_EQ(removed, 64);
}

TEST(SurfelFusionTest, TheModelStopsGrowingAtItsLimit) {
  SurfelFusionConfig config;
  config.max_surfels = 500;
  SurfelFusion fusion(config);
  const FusionFrameStats stats =
      fusion.integrate(planeFrame(0.6, 0.001, 1), Eigen::Isometry3d::Identity());
  EXPECT_EQ(fusion.surfels().size(), 500u);
  EXPECT_EQ(stats.added, 500);
  EXPECT_EQ(stats.refused, 64 * 48 - 500);
  EXPECT_TRUE(fusion.capacityReached());
  fusion.integrate(planeFrame(0.6, 0.001, 2), Eigen::Isometry3d::Identity());
  EXPECT_LE(fusion.surfels().size(), 500u);
}

TEST(SurfelFusionTest, RejectsBadConfigurationAndInput) {
  SurfelFusionConfig config;
  config.stable_confidence = 0.0;
  EXPECT_THROW(SurfelFusion{config}, std::invalid_argument);
  config = SurfelFusionConfig{};
  config.supersampling = 0;
  EXPECT_THROW(SurfelFusion{config}, std::invalid_argument);

  SurfelFusion fusion{SurfelFusionConfig{}};
  auto frame = planeFrame(0.6, 0.001, 1);
  frame.normals.pop_back();
  EXPECT_THROW(fusion.integrate(frame, Eigen::Isometry3d::Identity()), std::invalid_argument);
  Eigen::Isometry3d bad_pose = Eigen::Isometry3d::Identity();
  bad_pose.translation().x() = std::nan("");
  EXPECT_THROW(fusion.integrate(planeFrame(0.6, 0.001, 1), bad_pose), std::invalid_argument);
  EXPECT_TRUE(fusion.surfels().empty());
}

}  // namespace
}  // namespace vicc_fusion
