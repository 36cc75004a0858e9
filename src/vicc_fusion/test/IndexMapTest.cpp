// The supersampled index map: which cell of which pixel a surfel lands in, nearest-wins on a
// shared cell, clearing between renders, and surfels that must not be drawn.
#include <gtest/gtest.h>

#include <cmath>

#include "synthetic_frames.hpp"
#include "vicc_fusion/index_map.hpp"

namespace vicc_fusion {
namespace {

using test::smallCamera;

constexpr int kFactor = 4;

/// A surfel whose camera-frame projection (identity pose) is pixel coordinate (x, y) at depth z.
Surfel surfelAtPixel(float x, float y, float z) {
  const vicc_tracking::PinholeIntrinsics camera = smallCamera();
  Surfel surfel;
  surfel.position =
      Eigen::Vector3f((x - camera.cx) * z / camera.fx, (y - camera.cy) * z / camera.fy, z);
  return surfel;
}

/// Number of non-empty cells over the whole map.
int occupiedCells(const IndexMap& map, const vicc_tracking::PinholeIntrinsics& camera) {
  int occupied = 0;
  for (int v = 0; v < camera.height; ++v) {
    for (int u = 0; u < camera.width; ++u) {
      const int* cells = map.pixelCells(u, v);
      for (int c = 0; c < map.cellsPerPixel(); ++c) occupied += cells[c] != IndexMap::kEmpty;
    }
  }
  return occupied;
}

TEST(IndexMapTest, ASurfelLandsInTheSubPixelCellOfItsProjection) {
  // Pixel u covers [u - 0.5, u + 0.5): x = 10.3 is 0.8 into pixel 10, i.e. its cell 3 of 4;
  // y = 5.1 is 0.6 into row 5, i.e. cell row 2.
  IndexMap map;
  map.render({surfelAtPixel(10.3f, 5.1f, 0.8f)}, Eigen::Isometry3f::Identity(), smallCamera(),
             kFactor);
  EXPECT_EQ(map.factor(), kFactor);
  EXPECT_EQ(map.cellsPerPixel(), 16);
  const int* cells = map.pixelCells(10, 5);
  for (int c = 0; c < 16; ++c) EXPECT_EQ(cells[c], c == 2 * kFactor + 3 ? 0 : IndexMap::kEmpty);
  EXPECT_EQ(occupiedCells(map, smallCamera()), 1);
}

TEST(IndexMapTest, SixteenSurfelsInOnePixelFillItsSixteenCellsInRowMajorOrder) {
  SurfelVector surfels;
  const int u = 20, v = 17;  // an interior pixel
  for (int row = 0; row < kFactor; ++row) {
    for (int col = 0; col < kFactor; ++col) {  // cell centres: u - 0.5 + (col + 0.5) / 4
      surfels.push_back(surfelAtPixel(u - 0.5f + (col + 0.5f) / kFactor,
                                      v - 0.5f + (row + 0.5f) / kFactor, 1.0f));
    }
  }
  IndexMap map;
  map.render(surfels, Eigen::Isometry3f::Identity(), smallCamera(), kFactor);
  const int* cells = map.pixelCells(u, v);
  for (int c = 0; c < 16; ++c) EXPECT_EQ(cells[c], c) << "cell " << c;
  EXPECT_EQ(occupiedCells(map, smallCamera()), 16);
}

TEST(IndexMapTest, TheNearestSurfelOnACellWinsWhateverTheOrder) {
  const Surfel far = surfelAtPixel(12.1f, 7.1f, 1.5f);
  const Surfel near = surfelAtPixel(12.1f, 7.1f, 0.5f);
  IndexMap map;
  map.render({far, near}, Eigen::Isometry3f::Identity(), smallCamera(), kFactor);
  EXPECT_EQ(map.pixelCells(12, 7)[2 * kFactor + 2], 1);
  map.render({near, far}, Eigen::Isometry3f::Identity(), smallCamera(), kFactor);
  EXPECT_EQ(map.pixelCells(12, 7)[2 * kFactor + 2], 0);
  EXPECT_EQ(occupiedCells(map, smallCamera()), 1);
}

TEST(IndexMapTest, ImageBordersFollowThePixelConvention) {
  const vicc_tracking::PinholeIntrinsics camera = smallCamera();
  const float right = camera.width - 0.5f, bottom = camera.height - 0.5f;
  const SurfelVector surfels = {
      surfelAtPixel(-0.49f, -0.49f, 1.f),                 // 0: first cell of pixel (0, 0)
      surfelAtPixel(right - 0.01f, bottom - 0.01f, 1.f),  // 1: last cell of the last pixel
      surfelAtPixel(-0.51f, 3.f, 1.f),                    // left of the image
      surfelAtPixel(right + 0.001f, 3.f, 1.f),            // right of the image
      surfelAtPixel(3.f, bottom + 0.001f, 1.f),           // below the image
  };
  IndexMap map;
  map.render(surfels, Eigen::Isometry3f::Identity(), camera, kFactor);
  EXPECT_EQ(map.pixelCells(0, 0)[0], 0);
  EXPECT_EQ(map.pixelCells(camera.width - 1, camera.height - 1)[15], 1);
  EXPECT_EQ(occupiedCells(map, camera), 2);
}

TEST(IndexMapTest, SurfelsBehindOnOrNearTheCameraPlaneAreNotDrawn) {
  Surfel behind = surfelAtPixel(10.f, 10.f, 1.f);
  behind.position.z() = -1.f;
  Surfel on_plane = behind;
  on_plane.position.z() = 0.f;
  // Just in front of the camera plane, 1 m off axis: the projection is far outside the image
  // (beyond the int range), it must be skipped, not wrapped into a cell.
  Surfel grazing;
  grazing.position = Eigen::Vector3f(1.f, 1.f, 1e-12f);
  Surfel not_finite;
  not_finite.position = Eigen::Vector3f(NAN, 0.f, 1.f);
  IndexMap map;
  map.render({behind, on_plane, grazing, not_finite}, Eigen::Isometry3f::Identity(), smallCamera(),
             kFactor);
  EXPECT_EQ(occupiedCells(map, smallCamera()), 0);
}

TEST(IndexMapTest, UsesTheCameraPoseAndReportsCameraFrameDepth) {
  // Camera 0.5 m along map x, turned 90 degrees about map y (optical axis along map +x): a
  // surfel 0.7 m in front of it, just off the axis, at pixel coordinate (31.6, 23.6).
  Eigen::Isometry3f camera_pose = Eigen::Isometry3f::Identity();
  camera_pose.linear() = Eigen::AngleAxisf(M_PI / 2, Eigen::Vector3f::UnitY()).toRotationMatrix();
  camera_pose.translation() = Eigen::Vector3f(0.5f, 0.f, 0.f);
  Surfel surfel;
  surfel.position = camera_pose * surfelAtPixel(31.6f, 23.6f, 0.7f).position;
  ASSERT_NEAR(surfel.position.x(), 1.2f, 1e-6f);
  IndexMap map;
  map.render({surfel}, camera_pose, smallCamera(), kFactor);
  // 31.6 is 0.1 into pixel 32, 23.6 0.1 into row 24: the first cell of pixel (32, 24).
  EXPECT_EQ(map.pixelCells(32, 24)[0], 0);
  EXPECT_NEAR(map.depthOf(surfel), 0.7f, 1e-6f);
}

TEST(IndexMapTest, ARenderClearsThePreviousOneAndFollowsAFactorChange) {
  IndexMap map;
  map.render({surfelAtPixel(10.1f, 10.1f, 1.f)}, Eigen::Isometry3f::Identity(), smallCamera(),
             kFactor);
  map.render({surfelAtPixel(40.1f, 30.1f, 1.f)}, Eigen::Isometry3f::Identity(), smallCamera(),
             kFactor);
  EXPECT_EQ(occupiedCells(map, smallCamera()), 1);
  EXPECT_EQ(map.pixelCells(40, 30)[2 * kFactor + 2], 0);

  map.render({surfelAtPixel(40.1f, 30.1f, 1.f)}, Eigen::Isometry3f::Identity(), smallCamera(), 1);
  EXPECT_EQ(map.cellsPerPixel(), 1);
  EXPECT_EQ(map.pixelCells(40, 30)[0], 0);
  EXPECT_EQ(occupiedCells(map, smallCamera()), 1);

  map.render({}, Eigen::Isometry3f::Identity(), smallCamera(), kFactor);
  EXPECT_EQ(occupiedCells(map, smallCamera()), 0);
}

}  // namespace
}  // namespace vicc_fusion
