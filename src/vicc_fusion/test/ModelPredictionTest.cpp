#include <gtest/gtest.h>

#include <cmath>

#include "synthetic_frames.hpp"
#include "vicc_fusion/model_prediction.hpp"
#include "vicc_fusion/surfel_fusion.hpp"

namespace vicc_fusion {
namespace {

using test::planeFrame;
using test::smallCamera;

SurfelVector stablePlane(double depth) {
  SurfelFusion fusion{SurfelFusionConfig{}};
  for (unsigned frame = 0; frame < 12; ++frame) {
    fusion.integrate(planeFrame(depth, 0.0, frame), Eigen::Isometry3d::Identity());
  }
  return fusion.surfels();
}

ModelPredictionConfig predictionConfig() {
  ModelPredictionConfig config;
  config.stable_confidence = SurfelFusionConfig{}.stable_confidence;
  return config;
}

TEST(ModelPredictionTest, RendersAPlaneAtItsDepthWithItsNormal) {
  const SurfelVector model = stablePlane(0.6);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation().z() = -0.05;  // step back: the plane is 0.65 m away
  const auto level = renderModel(model, pose, smallCamera(), predictionConfig());
  ASSERT_EQ(level.vertices.size(), 64u * 48u);
  EXPECT_GT(level.valid_normals, 0.8 * 64 * 48);
  for (size_t i = 0; i < level.vertices.size(); ++i) {
    if (!level.hasNormal(static_cast<int>(i))) continue;
    ASSERT_NEAR(level.vertices[i].z(), 0.65, 1e-4);
    ASSERT_NEAR(level.normals[i].z(), -1.0, 1e-5);
    ASSERT_NEAR(level.depth(static_cast<int>(i) / 64, static_cast<int>(i) % 64), 0.65, 1e-4);
  }
}

TEST(ModelPredictionTest, SplatsFillThePixelsBetweenSurfelCentres) {
  // Seen from closer, each surfel covers more than a pixel: no holes in the middle.
  const SurfelVector model = stablePlane(0.6);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation().z() = 0.2;  // 0.4 m away: surfel spacing 1.5 px
  const auto level = renderModel(model, pose, smallCamera(), predictionConfig());
  int holes = 0;
  for (int v = 16; v < 32; ++v) {
    for (int u = 24; u < 40; ++u) holes += !level.hasNormal(v * 64 + u);
  }
  EXPECT_EQ(holes, 0);
}

TEST(ModelPredictionTest, ADiscCoversExactlyThePixelCentresInsideIt) {
  // One fronto-parallel disc at a fractional pixel position: its footprint is a circle of
  // radius r f / z. Small footprints take the 3x3 fast path, large ones the row scan; both
  // must cover exactly the pixel centres inside the circle, at the disc's depth.
  const vicc_tracking::PinholeIntrinsics k = smallCamera();
  ModelPredictionConfig config = predictionConfig();
  config.splat_radius_scale = 1.0;
  for (const double radius_px : {0.8, 1.3, 1.45, 2.2, 3.7}) {
    for (const double u0 : {31.3, 0.4}) {  // inside, and at the image border
      const double v0 = 23.62, z = 0.5;
      Surfel surfel;
      surfel.position = Eigen::Vector3f((u0 - k.cx) * z / k.fx, (v0 - k.cy) * z / k.fy, z);
      surfel.normal = -Eigen::Vector3f::UnitZ();
      surfel.radius = static_cast<float>(radius_px * z / k.fx);
      surfel.confidence = 5.f;
      const auto level = renderModel({surfel}, Eigen::Isometry3d::Identity(), k, config);
      int expected = 0;
      for (int v = 0; v < k.height; ++v) {
        for (int u = 0; u < k.width; ++u) {
          const double r2 = ((u - u0) * (u - u0) + (v - v0) * (v - v0)) / (radius_px * radius_px);
          if (std::abs(r2 - 1.0) < 1e-3) continue;  // on the rim: rounding may go either way
          const bool inside = r2 < 1.0;
          expected += inside;
          ASSERT_EQ(level.hasNormal(v * k.width + u), inside)
              << "radius " << radius_px << " px, centre u " << u0 << ", pixel " << u << "," << v;
          if (inside) {
            ASSERT_NEAR(level.vertices[v * k.width + u].z(), z, 1e-5);
          }
        }
      }
      EXPECT_EQ(level.valid_normals, expected);
    }
  }
}

TEST(ModelPredictionTest, DrawsOnlyStableFrontFacingSurfels) {
  SurfelVector model = stablePlane(0.6);
  for (Surfel& s : model) s.confidence = 1.0f;  // unstable
  EXPECT_EQ(renderModel(model, Eigen::Isometry3d::Identity(), smallCamera(), predictionConfig())
                .valid_normals,
            0);
  model = stablePlane(0.6);
  for (Surfel& s : model) s.normal = Eigen::Vector3f::UnitZ();  // facing away
  EXPECT_EQ(renderModel(model, Eigen::Isometry3d::Identity(), smallCamera(), predictionConfig())
                .valid_normals,
            0);
}

TEST(ModelPredictionTest, PyramidMatchesTheFrameLayout) {
  const SurfelVector model = stablePlane(0.6);
  vicc_tracking::DepthPyramid frame{planeFrame(0.6, 0.0, 1)};
  frame.push_back(planeFrame(0.6, 0.0, 1));
  frame.back().intrinsics = frame.front().intrinsics.halved();
  const auto pyramid = predictPyramid(model, Eigen::Isometry3d::Identity(), frame,
                                      vicc_tracking::PreprocessingConfig{}, predictionConfig());
  ASSERT_EQ(pyramid.size(), 2u);
  EXPECT_EQ(pyramid[1].intrinsics.width, 32);
  EXPECT_EQ(pyramid[1].depth.cols, 32);
  EXPECT_EQ(pyramid[1].vertices.size(), 32u * 24u);
  EXPECT_GT(pyramid[1].valid_normals, 0.7 * 32 * 24);
}

}  // namespace
}  // namespace vicc_fusion
