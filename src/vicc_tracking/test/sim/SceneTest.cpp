#include <gtest/gtest.h>

#include "vicc_tracking/sim/scene.hpp"

using namespace vicc_tracking::sim;

namespace {

Primitive box(Eigen::Vector3d center, Eigen::Vector3d half, double yaw = 0.0) {
  return {PrimitiveType::kBox, center, half, yaw};
}

TEST(SceneTest, RaycastHitsTheNearestSurfaceExactly) {
  const Scene scene({box({0, 0, -0.5}, {1, 1, 0.5}),  // top face at z = 0
                     {PrimitiveType::kEllipsoid, {0, 0, 0.2}, {0.1, 0.1, 0.1}, 0.0},
                     {PrimitiveType::kCylinder, {0.5, 0, 0.1}, {0.05, 0.05, 0.1}, 0.0}});
  const Eigen::Vector3d down(0, 0, -1);
  EXPECT_NEAR(*scene.raycast({0, 0, 1}, down), 0.7, 1e-12);        // sphere top at 0.3
  EXPECT_NEAR(*scene.raycast({0.5, 0, 1}, down), 0.8, 1e-12);      // cylinder cap at 0.2
  EXPECT_NEAR(*scene.raycast({-0.5, 0.5, 1}, down), 1.0, 1e-12);   // table
  EXPECT_NEAR(*scene.raycast({0.5, -1, 0.1}, {0, 1, 0}), 0.95, 1e-12);  // cylinder side
  // Direction need not be unit length: the parameter scales with it.
  EXPECT_NEAR(*scene.raycast({-0.5, 0.5, 1}, 2.0 * down), 0.5, 1e-12);
  EXPECT_FALSE(scene.raycast({0, 0, 1}, {0, 0, 1}).has_value());
}

TEST(SceneTest, YawRotatesBoxes) {
  const Scene scene({box({0, 0, 0}, {0.5, 0.05, 0.05}, M_PI / 2)});  // long axis along y now
  EXPECT_TRUE(scene.raycast({0, 0.4, 1}, {0, 0, -1}).has_value());
  EXPECT_FALSE(scene.raycast({0.4, 0, 1}, {0, 0, -1}).has_value());
}

TEST(SceneTest, SurfaceSamplesLieOnTheSurfaceWithOutwardNormals) {
  const Scene scene({box({0, 0, 0}, {0.1, 0.2, 0.05}, 0.3),
                     {PrimitiveType::kEllipsoid, {0.5, 0, 0}, {0.1, 0.05, 0.08}, 0.0}});
  const auto points = scene.sampleSurface(0.01);
  ASSERT_GT(points.size(), 500u);
  for (const SurfacePoint& point : points) {
    // Casting back along the normal from outside hits the point itself.
    const Eigen::Vector3d origin = point.position + 0.05 * point.normal;
    const auto hit = scene.raycast(origin, -point.normal);
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(*hit, 0.05, 1e-6);
  }
}

}  // namespace
