#include <gtest/gtest.h>

#include <algorithm>
#include <tuple>

#include "synthetic_frames.hpp"
#include "vicc_fusion/surfel_fusion.hpp"
#include "vicc_fusion/surfel_order.hpp"

namespace vicc_fusion {
namespace {

using test::planeFrame;
using test::smallCamera;

Surfel surfelAt(float x, float y, float z, float confidence) {
  Surfel surfel;
  surfel.position = Eigen::Vector3f(x, y, z);
  surfel.normal = -Eigen::Vector3f::UnitZ();
  surfel.radius = 0.002f;
  surfel.confidence = confidence;
  return surfel;
}

/// Pixel a camera at the origin (looking along +z) sees a map point in.
int pixelOf(const Surfel& surfel, const vicc_tracking::PinholeIntrinsics& k) {
  const Eigen::Vector3f& p = surfel.position;
  const int u = static_cast<int>(k.fx * p.x() / p.z() + k.cx + 0.5f);
  const int v = static_cast<int>(k.fy * p.y() / p.z() + k.cy + 0.5f);
  return v * k.width + u;
}

auto contentKey(const Surfel& s) {
  return std::make_tuple(s.position.x(), s.position.y(), s.position.z(), s.confidence);
}

TEST(SurfelOrderTest, SortsByPixelKeepingContentAndPuttingUnseenLast) {
  const vicc_tracking::PinholeIntrinsics k = smallCamera();
  SurfelVector surfels = {surfelAt(0.05f, 0.04f, 0.6f, 1.f),   surfelAt(0.f, 0.f, -0.5f, 2.f),
                          surfelAt(-0.05f, -0.04f, 0.6f, 3.f), surfelAt(0.f, 0.f, 0.6f, 4.f),
                          surfelAt(5.f, 0.f, 0.6f, 5.f),       surfelAt(0.f, 0.001f, 0.6f, 6.f)};
  SurfelVector before = surfels;
  SurfelOrder order;
  order.sortByPixel(surfels, Eigen::Isometry3f::Identity(), k);

  ASSERT_EQ(surfels.size(), before.size());
  auto by_content = [](const Surfel& a, const Surfel& b) { return contentKey(a) < contentKey(b); };
  std::sort(before.begin(), before.end(), by_content);
  SurfelVector sorted_content = surfels;
  std::sort(sorted_content.begin(), sorted_content.end(), by_content);
  for (size_t i = 0; i < before.size(); ++i) {
    EXPECT_EQ(contentKey(sorted_content[i]), contentKey(before[i])) << "only the order changes";
  }
  // Visible surfels in row-major pixel order (ties keep their order), then the unseen ones
  // (behind the camera, outside the image) in their previous order.
  EXPECT_EQ(surfels[0].confidence, 3.f);
  EXPECT_EQ(surfels[1].confidence, 4.f);
  EXPECT_EQ(surfels[2].confidence, 6.f);
  EXPECT_EQ(surfels[3].confidence, 1.f);
  EXPECT_EQ(surfels[4].confidence, 2.f);
  EXPECT_EQ(surfels[5].confidence, 5.f);
  for (size_t i = 1; i < 4; ++i) EXPECT_LE(pixelOf(surfels[i - 1], k), pixelOf(surfels[i], k));
}

TEST(SurfelOrderTest, SortingTheModelDoesNotChangeWhatFusionBuilds) {
  // The order is for speed only: the same views give the same model with or without sorting.
  SurfelFusionConfig unsorted_config;
  unsorted_config.sort_interval = 0;
  SurfelFusionConfig sorted_config;
  sorted_config.sort_interval = 1;
  SurfelFusion unsorted(unsorted_config), sorted(sorted_config);
  for (unsigned view = 1; view <= 6; ++view) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = Eigen::Vector3d(0.003 * view, -0.002 * (view % 3), 0.0);
    const vicc_tracking::DepthLevel frame = planeFrame(0.6, 0.002, view);
    unsorted.integrate(frame, pose);
    sorted.integrate(frame, pose);
  }
  ASSERT_EQ(sorted.surfels().size(), unsorted.surfels().size());
  EXPECT_EQ(sorted.stableCount(), unsorted.stableCount());
  double z_sorted = 0.0, z_unsorted = 0.0;
  for (const Surfel& s : sorted.surfels()) z_sorted += s.position.z();
  for (const Surfel& s : unsorted.surfels()) z_unsorted += s.position.z();
  EXPECT_NEAR(z_sorted, z_unsorted, 1e-6 * unsorted.surfels().size());
}

TEST(SurfelOrderTest, NegativeSortIntervalIsRejected) {
  SurfelFusionConfig config;
  config.sort_interval = -1;
  EXPECT_THROW(config.validate(), std::invalid_argument);
}

}  // namespace
}  // namespace vicc_fusion
