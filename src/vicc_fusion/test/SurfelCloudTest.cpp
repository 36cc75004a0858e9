// The surfel model as PointCloud2 for rviz: every field by name, the transform applied to
// positions and normals, and the rgb grey level shaded from the normal -- the same for two
// surfels at different heights, different for different orientations.
#include <gtest/gtest.h>

#include <sensor_msgs/point_cloud2_iterator.h>

#include <cstring>

#include "vicc_fusion/ros/surfel_cloud.hpp"
#include "vicc_fusion/ros/surfel_shading.hpp"

namespace {

using namespace vicc_fusion;

Surfel surfel(const Eigen::Vector3f& position, const Eigen::Vector3f& normal) {
  Surfel s;
  s.position = position;
  s.normal = normal.normalized();
  s.radius = 0.002f;
  s.confidence = 3.f;
  return s;
}

std::uint8_t greyAt(const sensor_msgs::PointCloud2& cloud, std::size_t index) {
  sensor_msgs::PointCloud2ConstIterator<float> rgb(cloud, "rgb");
  rgb += index;
  std::uint32_t packed = 0;
  std::memcpy(&packed, &*rgb, sizeof packed);
  const std::uint8_t r = (packed >> 16) & 0xff, g = (packed >> 8) & 0xff, b = packed & 0xff;
  EXPECT_EQ(r, g);
  EXPECT_EQ(g, b);
  EXPECT_EQ(packed >> 24, 0u);
  return r;
}

TEST(SurfelShadingTest, FacingTheLightIsBrightEdgeOnIsAmbientBothSidesAlike) {
  const SurfelShading shading;
  const Eigen::Vector3f towards_light = shading.light.normalized();
  EXPECT_NEAR(shadedGrey(towards_light, shading), 1.f, 1e-5f);
  EXPECT_NEAR(shadedGrey(-towards_light, shading), 1.f, 1e-5f);
  const Eigen::Vector3f edge_on = towards_light.unitOrthogonal();
  EXPECT_NEAR(shadedGrey(edge_on, shading), shading.ambient, 1e-5f);
  EXPECT_FLOAT_EQ(shadedGrey(Eigen::Vector3f::Zero(), shading), shading.ambient);
  EXPECT_FLOAT_EQ(shadedGrey(Eigen::Vector3f(NAN, 0, 0), shading), shading.ambient);
  EXPECT_EQ(packedGrey(1.f), 0x00ffffffu);
  EXPECT_EQ(packedGrey(0.f), 0u);
  EXPECT_EQ(packedGrey(2.f), 0x00ffffffu);
}

TEST(SurfelCloudTest, FieldsTransformAndShadingByNormalNotHeight) {
  const SurfelVector surfels = {surfel({0, 0, 0}, {0, 0, 1}), surfel({0, 0, 1.5f}, {0, 0, 1}),
                                surfel({0.1f, 0, 0}, {1, 0, 0})};
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
  transform.translation() = Eigen::Vector3d(1, 2, 3);
  const auto cloud = toPointCloud2(surfels, transform, "map", ros::Time(5));
  EXPECT_EQ(cloud.header.frame_id, "map");
  EXPECT_EQ(cloud.width, 3u);
  for (const char* name : {"x", "normal_x", "radius", "confidence", "intensity", "rgb"}) {
    bool found = false;
    for (const auto& field : cloud.fields) found |= field.name == name;
    EXPECT_TRUE(found) << name;
  }
  sensor_msgs::PointCloud2ConstIterator<float> z(cloud, "z");
  EXPECT_FLOAT_EQ(z[0], 3.f);
  sensor_msgs::PointCloud2ConstIterator<float> intensity(cloud, "intensity");
  EXPECT_TRUE(std::isnan(*intensity));
  // Same orientation, 1.5 m apart in height: the same grey. Another orientation: another.
  EXPECT_EQ(greyAt(cloud, 0), greyAt(cloud, 1));
  EXPECT_NE(greyAt(cloud, 0), greyAt(cloud, 2));
  EXPECT_EQ(greyAt(cloud, 0), packedGrey(shadedGrey(Eigen::Vector3f::UnitZ())) & 0xff);
}

}  // namespace
