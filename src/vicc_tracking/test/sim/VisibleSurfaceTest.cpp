#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>

#include "vicc_tracking/sim/visible_surface.hpp"

using namespace vicc_tracking::sim;

namespace {

TEST(VisibleSurfaceTest, KeepsOnlySurfaceTheCameraSaw) {
  const RigSimulator rig(loadScenario("short_test"));
  VisibleSurfaceConfig config;
  config.spacing = 0.004;
  const auto all = rig.sampleSurface(config.spacing);
  const auto visible = visibleSurface(rig, config);
  ASSERT_GT(visible.size(), 1000u);
  EXPECT_LT(visible.size(), all.size());
  const Eigen::Vector3d start = rig.cameraPose(0.0).translation();
  for (const SurfacePoint& point : visible) {
    // Downward flat faces (the table's underside, the cubes' bottoms) are never seen by a
    // camera above the table; nothing is further than the sensor's range.
    ASSERT_GT(point.normal.z(), -0.99);
    ASSERT_LT((point.position - start).norm(), rig.scenario().tof.max_range + 1.0);
  }
}

TEST(VisibleSurfaceTest, WritesABinaryPlyWithNormals) {
  const std::vector<SurfacePoint> points = {
      {Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(0, 0, 1)},
      {Eigen::Vector3d(-1, 0.5, 0), Eigen::Vector3d(1, 0, 0)}};
  const std::string path = ::testing::TempDir() + "/vicc_visible_surface.ply";
  writeSurfacePly(path, points);
  std::ifstream in(path, std::ios::binary);
  const std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t body = content.find("end_header\n");
  ASSERT_NE(body, std::string::npos);
  EXPECT_NE(content.find("element vertex 2"), std::string::npos);
  ASSERT_EQ(content.size() - body - 11, 2 * 7 * sizeof(float));
  float first[7];
  std::memcpy(first, content.data() + body + 11, sizeof(first));
  EXPECT_FLOAT_EQ(first[2], 3.f);
  EXPECT_FLOAT_EQ(first[5], 1.f);
  std::remove(path.c_str());
  EXPECT_THROW(writeSurfacePly("/nonexistent/dir/x.ply", points), std::runtime_error);
}

}  // namespace
