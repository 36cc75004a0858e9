#include <gtest/gtest.h>

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
