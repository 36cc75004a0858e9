#include <gtest/gtest.h>

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
