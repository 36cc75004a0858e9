#include <gtest/gtest.h>

#include "synthetic_avatar.hpp"
#include "vicc_anatomy_viz/avatar_view/occlusion.hpp"
#include "vicc_anatomy_viz/avatar_view/view_preset.hpp"

namespace vicc_anatomy_viz::avatar_view {
namespace {

constexpr float kFov = 0.8f;

CameraModel frontCamera() {
  OrbitCamera orbit;
  orbit.focus = Eigen::Vector3f(0.f, 0.f, 1.f);
  orbit.distance = 3.f;
  return cameraModel(orbit, kFov, 1.f);
}

TEST(OcclusionTest, BoundingSphereOfACube) {
  const Sphere sphere = boundingSphere(testing::cube({1.f, 2.f, 3.f}, 0.5f));
  EXPECT_NEAR((sphere.centre - Eigen::Vector3f(1.f, 2.f, 3.f)).norm(), 0.f, 1e-6f);
  EXPECT_NEAR(sphere.radius, 0.5f * std::sqrt(3.f), 1e-6f);
  EXPECT_EQ(boundingSphere({}).radius, 0.f);
}

TEST(OcclusionTest, ProjectionPutsThePatientsRightOnTheImagesLeftFromTheFront) {
  const CameraModel camera = frontCamera();
  Eigen::Vector2f right_hand, left_hand, head;
  ASSERT_TRUE(projectToPixel({0.f, -0.5f, 1.f}, camera, 400, 400, right_hand));
  ASSERT_TRUE(projectToPixel({0.f, 0.5f, 1.f}, camera, 400, 400, left_hand));
  ASSERT_TRUE(projectToPixel({0.f, 0.f, 1.5f}, camera, 400, 400, head));
  EXPECT_LT(right_hand.x(), 200.f);
  EXPECT_GT(left_hand.x(), 200.f);
  EXPECT_NEAR(right_hand.y(), 200.f, 1e-3f);
  EXPECT_LT(head.y(), 200.f);  // up is up
  // The image offset of 0.5 m at 3 m: f * 0.5 / 3 in NDC, f = 1 / tan(fov / 2).
  const float expected = 200.f * (1.f / std::tan(0.5f * kFov)) * 0.5f / 3.f;
  EXPECT_NEAR(200.f - right_hand.x(), expected, 1e-2f);
  Eigen::Vector2f behind;
  EXPECT_FALSE(projectToPixel({5.f, 0.f, 1.f}, camera, 400, 400, behind));
}

TEST(OcclusionTest, ANearerOverlappingStructureOccludesFartherOrAsideOnesDoNot) {
  const Sphere target{{0.f, 0.f, 1.f}, 0.05f};
  const std::vector<Sphere> candidates = {
      {{0.3f, 0.02f, 1.f}, 0.05f},  // between camera and target, overlapping
      {{-0.3f, 0.0f, 1.f}, 0.05f},  // behind the target
      {{0.3f, 0.6f, 1.f}, 0.05f},   // in front but far to the side
      {{4.f, 0.f, 1.f}, 0.05f}};    // behind the camera
  const std::vector<bool> occludes = findOccluders({target}, candidates, frontCamera());
  EXPECT_EQ(occludes, (std::vector<bool>{true, false, false, false}));
  // From the back the roles of the first two swap.
  OrbitCamera back;
  back.focus = Eigen::Vector3f(0.f, 0.f, 1.f);
  back.distance = 3.f;
  back.yaw = 3.14159265f;
  EXPECT_EQ(findOccluders({target}, candidates, cameraModel(back, kFov, 1.f)),
            (std::vector<bool>{false, true, false, false}));
}

TEST(OcclusionTest, WholeBodyCameraShowsTheBoxFromTheNamedSide) {
  const Eigen::Vector3f min(-0.15f, -0.4f, 0.f), max(0.15f, 0.4f, 1.66f);
  const std::vector<std::pair<std::string, Eigen::Vector3f>> views = {
      {"front", Eigen::Vector3f::UnitX()},
      {"back", -Eigen::Vector3f::UnitX()},
      {"left", Eigen::Vector3f::UnitY()},
      {"right", -Eigen::Vector3f::UnitY()}};
  for (const auto& [name, eye_direction] : views) {
    const auto view = bodyViewFromString(name);
    ASSERT_TRUE(view.has_value());
    const OrbitCamera orbit = wholeBodyCamera(*view, min, max, kFov, 0.6f);
    EXPECT_GT((orbit.eye() - orbit.focus).normalized().dot(eye_direction), 0.999f) << name;
    const CameraModel camera = cameraModel(orbit, kFov, 0.6f);
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3f point(corner & 1 ? max.x() : min.x(), corner & 2 ? max.y() : min.y(),
                                  corner & 4 ? max.z() : min.z());
      Eigen::Vector2f pixel;
      ASSERT_TRUE(projectToPixel(point, camera, 600, 1000, pixel));
      EXPECT_GT(pixel.x(), 0.f) << name;
      EXPECT_LT(pixel.x(), 600.f) << name;
      EXPECT_GT(pixel.y(), 0.f) << name;
      EXPECT_LT(pixel.y(), 1000.f) << name;
    }
  }
  EXPECT_FALSE(bodyViewFromString("top").has_value());
}

}  // namespace
}  // namespace vicc_anatomy_viz::avatar_view
