#include <gtest/gtest.h>

#include <cstdio>

#include <pcl/io/ply_io.h>

#include "vicc_fusion/cloud_accumulator.hpp"

using namespace vicc_fusion;

namespace {

/// A full-resolution depth level of a fronto-parallel plane at z = depth.
vicc_tracking::DepthLevel planeLevel(float depth, int width = 40, int height = 30) {
  vicc_tracking::DepthLevel level;
  level.intrinsics = {width, height, 50.f, 50.f, width / 2.f, height / 2.f};
  for (int v = 0; v < height; ++v) {
    for (int u = 0; u < width; ++u) {
      level.vertices.emplace_back((u - width / 2.f) * depth / 50.f,
                                  (v - height / 2.f) * depth / 50.f, depth);
      level.normals.emplace_back(0.f, 0.f, -1.f);
      level.radii.push_back(0.001f);
    }
  }
  return level;
}

TEST(CloudAccumulatorTest, TwoViewsOfOnePlaneMergeInTheMapFrame) {
  CloudAccumulatorConfig config;
  config.voxel_size = 0.01;
  CloudAccumulator accumulator(config);
  // The same wall at map z = 1 seen from the origin and from a camera 0.2 m closer.
  accumulator.addFrame(planeLevel(1.0f), Eigen::Isometry3d::Identity());
  Eigen::Isometry3d closer = Eigen::Isometry3d::Identity();
  closer.translation().z() = 0.2;
  accumulator.addFrame(planeLevel(0.8f), closer);
  EXPECT_EQ(accumulator.rawPointCount(), 2u * 40 * 30);
  const auto cloud = accumulator.cloud();
  ASSERT_FALSE(cloud.empty());
  EXPECT_LT(cloud.size(), accumulator.rawPointCount());
  for (const auto& point : cloud) {
    EXPECT_NEAR(point.z, 1.0, 0.006);  // one voxel of tolerance for the averaging
    EXPECT_NEAR(point.normal_z, -1.0, 1e-4);
  }
}

TEST(CloudAccumulatorTest, InvalidPixelsAreSkipped) {
  CloudAccumulator accumulator(CloudAccumulatorConfig{});
  vicc_tracking::DepthLevel level = planeLevel(1.0f);
  for (auto& vertex : level.vertices) vertex.z() = 0.f;
  accumulator.addFrame(level, Eigen::Isometry3d::Identity());
  EXPECT_EQ(accumulator.rawPointCount(), 0u);
  EXPECT_THROW(saveCloudPly("/tmp/vicc_empty_cloud.ply", accumulator.cloud()), std::runtime_error);
}

TEST(CloudAccumulatorTest, PlyRoundTripKeepsPointsAndNormals) {
  CloudAccumulator accumulator(CloudAccumulatorConfig{});
  accumulator.addFrame(planeLevel(0.5f), Eigen::Isometry3d::Identity());
  const auto cloud = accumulator.cloud();
  const std::string path = ::testing::TempDir() + "vicc_cloud_test.ply";
  saveCloudPly(path, cloud);
  pcl::PointCloud<pcl::PointNormal> loaded;
  ASSERT_EQ(pcl::io::loadPLYFile(path, loaded), 0);
  ASSERT_EQ(loaded.size(), cloud.size());
  EXPECT_FLOAT_EQ(loaded[3].x, cloud[3].x);
  EXPECT_FLOAT_EQ(loaded[3].normal_z, cloud[3].normal_z);
  std::remove(path.c_str());
}

TEST(CloudAccumulatorTest, RejectsInvalidVoxelSize) {
  CloudAccumulatorConfig config;
  config.voxel_size = 0.0;
  EXPECT_THROW(CloudAccumulator{config}, std::invalid_argument);
}

}  // namespace
