#include <gtest/gtest.h>

#include <limits>

#include <cstdio>
#include <string>

#include "synthetic_frames.hpp"
#include "vicc_fusion/surfel_fusion.hpp"
#include "vicc_fusion/surfel_io.hpp"

namespace vicc_fusion {
namespace {

std::string tempPath(const std::string& name) {
  return ::testing::TempDir() + "/vicc_fusion_" + name;
}

TEST(SurfelIoTest, PlyRoundTripKeepsGeometryRadiusAndConfidence) {
  SurfelFusion fusion{SurfelFusionConfig{}};
  for (unsigned frame = 0; frame < 3; ++frame) {
    fusion.integrate(test::planeFrame(0.6, 0.001, frame), Eigen::Isometry3d::Identity());
  }
  const SurfelVector& original = fusion.surfels();
  const std::string path = tempPath("roundtrip.ply");
  saveSurfelsPly(path, original);
  const SurfelVector loaded = loadSurfelsPly(path);
  ASSERT_EQ(loaded.size(), original.size());
  for (size_t i = 0; i < loaded.size(); ++i) {
    ASSERT_TRUE(loaded[i].position.isApprox(original[i].position, 1e-6f));
    ASSERT_TRUE(loaded[i].normal.isApprox(original[i].normal, 1e-6f));
    ASSERT_FLOAT_EQ(loaded[i].radius, original[i].radius);
    ASSERT_FLOAT_EQ(loaded[i].confidence, original[i].confidence);
  }
  std::remove(path.c_str());
}

TEST(SurfelIoTest, GrayIsTheIntensityStretchedToTheBrightSurfels) {
  // A ToF amplitude fills a small part of its range: the PLY's gray spans 0..255 anyway, in
  // proportion; surfels without intensity are white.
  SurfelVector surfels(200);
  for (size_t i = 0; i < surfels.size(); ++i) {
    surfels[i].position = Eigen::Vector3f(0.001f * i, 0.f, 0.5f);
    surfels[i].radius = 0.001f;
    surfels[i].confidence = 5.f;
    surfels[i].intensity = 0.0001f * (i % 100);  // 0 .. 0.0099
  }
  surfels.back().intensity = 0.5f;  // one highlight does not set the scale
  surfels.front().intensity = std::numeric_limits<float>::quiet_NaN();
  const auto cloud = toPointCloud(surfels);
  EXPECT_EQ(cloud[0].r, 255);            // no intensity: white
  EXPECT_EQ(cloud[1].r, 3);              // 0.0001 / 0.0099 * 255
  EXPECT_EQ(cloud[99].r, 255);           // the bright ones
  EXPECT_EQ(cloud[150].r, cloud[50].r);  // same intensity, same gray
  EXPECT_NEAR(cloud[50].r, 0.0050 / 0.0099 * 255, 1.0);
  EXPECT_EQ(cloud[199].r, 255);  // the highlight saturates
  EXPECT_EQ(cloud[50].g, cloud[50].r);
}

TEST(SurfelIoTest, ClearErrorsForEmptyModelsAndMissingFiles) {
  EXPECT_THROW(saveSurfelsPly(tempPath("empty.ply"), {}), std::runtime_error);
  EXPECT_THROW(loadSurfelsPly(tempPath("does_not_exist.ply")), std::runtime_error);
}

TEST(SurfelIoTest, MeshOfAPlaneCoversIt) {
  SurfelFusion fusion{SurfelFusionConfig{}};
  fusion.integrate(test::planeFrame(0.6, 0.0, 1), Eigen::Isometry3d::Identity());
  const pcl::PolygonMesh mesh = meshSurfels(fusion.surfels());
  // A grid of n points triangulates into about 2n triangles.
  EXPECT_GT(mesh.polygons.size(), 1.5 * fusion.surfels().size());
  const std::string path = tempPath("mesh.ply");
  saveMeshPly(path, mesh);
  EXPECT_THROW(saveMeshPly(path, pcl::PolygonMesh{}), std::runtime_error);
  std::remove(path.c_str());
}

}  // namespace
}  // namespace vicc_fusion
