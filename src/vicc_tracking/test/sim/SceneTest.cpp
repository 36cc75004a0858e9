#include <gtest/gtest.h>

#include <cmath>

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

TEST(SceneTest, RaycastHitGivesThePrimitiveAndTheOutwardNormal) {
  const Scene scene({box({0, 0, -0.5}, {1, 1, 0.5}, 0.3),  // top face at z = 0
                     {PrimitiveType::kEllipsoid, {0, 0, 0.2}, {0.1, 0.2, 0.1}, 0.0},
                     {PrimitiveType::kCylinder, {0.5, 0, 0.1}, {0.05, 0.05, 0.1}, 0.0}});
  const Eigen::Vector3d down(0, 0, -1);
  auto hit = scene.raycastHit({-0.5, 0.5, 1}, down);  // table top
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->primitive, 0u);
  EXPECT_NEAR((hit->normal - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-12);
  hit = scene.raycastHit({-2, 0.1, -0.2}, {1, 0, 0});  // side face of the yawed box
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->normal.z(), 0.0, 1e-12);
  EXPECT_NEAR(hit->normal.dot(Eigen::Vector3d(-std::cos(0.3), -std::sin(0.3), 0)), 1.0, 1e-9);
  // Ellipsoid: the normal is the gradient of its implicit function, off the radial direction.
  hit = scene.raycastHit({0.05, 0.1, 1}, down);
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->primitive, 1u);
  const Eigen::Vector3d p =
      Eigen::Vector3d(0.05, 0.1, 1) + hit->t * down - Eigen::Vector3d(0, 0, 0.2);
  const Eigen::Vector3d gradient(p.x() / 0.01, p.y() / 0.04, p.z() / 0.01);
  EXPECT_NEAR((hit->normal - gradient.normalized()).norm(), 0.0, 1e-9);
  hit = scene.raycastHit({0.5, 0, 1}, down);  // cylinder cap
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->primitive, 2u);
  EXPECT_NEAR((hit->normal - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-12);
  hit = scene.raycastHit({0.5, -1, 0.1}, {0, 1, 0});  // cylinder side
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR((hit->normal - Eigen::Vector3d(0, -1, 0)).norm(), 0.0, 1e-12);
  EXPECT_FALSE(scene.raycastHit({0, 0, 1}, {0, 0, 1}).has_value());
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
