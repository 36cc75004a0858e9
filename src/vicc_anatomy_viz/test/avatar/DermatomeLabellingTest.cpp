// Dermatomes on the default skin: cover the skin, every key point in its own dermatome, one
// connected region each, left and right mirror images, bands ordered along the body.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <map>
#include <numeric>
#include <queue>
#include <set>

#include "avatar_test_support.hpp"
#include "vicc_anatomy_viz/avatar/avatar_report.hpp"
#include "vicc_anatomy_viz/avatar/dermatome_labelling.hpp"
#include "vicc_anatomy_viz/avatar/mesh_geometry.hpp"

namespace vicc_anatomy_viz::avatar {
namespace {

using test::defaultAvatar;

Eigen::Vector3f centroid(const TriangleMesh& mesh, int triangle) {
  const Eigen::Vector3i& t = mesh.triangles[triangle];
  return (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3;
}

/// Region index of every skin triangle.
std::vector<int> labels(const AvatarModel& model) {
  std::vector<int> label(model.skin.triangles.size(), -1);
  for (std::size_t r = 0; r < model.skin_regions.size(); ++r) {
    for (int t : model.skin_regions[r].triangles) label[t] = static_cast<int>(r);
  }
  return label;
}

int nearestTriangle(const TriangleMesh& mesh, const Eigen::Vector3f& point) {
  int best = 0;
  float best_distance = 1e9f;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const float distance = (centroid(mesh, static_cast<int>(t)) - point).squaredNorm();
    if (distance < best_distance) {
      best_distance = distance;
      best = static_cast<int>(t);
    }
  }
  return best;
}

/// Mean centroid of the region's triangles, of those inside `box` (min, max corners) if given.
Eigen::Vector3f meanCentroid(const AvatarModel& model, const std::string& level, Side side,
                             const Eigen::AlignedBox3f& box = Eigen::AlignedBox3f(
                                 Eigen::Vector3f::Constant(-10), Eigen::Vector3f::Constant(10))) {
  const SkinRegion* region = model.skinRegion("dermatome_" + level, side);
  Eigen::Vector3f sum = Eigen::Vector3f::Zero();
  int count = 0;
  for (int t : region->triangles) {
    const Eigen::Vector3f c = centroid(model.skin, t);
    if (!box.contains(c)) continue;
    sum += c;
    ++count;
  }
  EXPECT_GT(count, 0) << level << " " << toString(side);
  return sum / static_cast<float>(std::max(count, 1));
}

TEST(DermatomeLabellingTest, RegionsCoverTheSkinOnceExceptTheTrigeminalFace) {
  const AvatarBuild& build = defaultAvatar();
  const AvatarModel& model = build.model;
  EXPECT_EQ(model.skin_regions.size(), 2 * dermatomeLevels().size());
  std::vector<int> count(model.skin.triangles.size(), 0);
  for (const SkinRegion& region : model.skin_regions) {
    EXPECT_FALSE(region.triangles.empty()) << region.display_name;
    for (int t : region.triangles) ++count[t];
  }
  const Eigen::Vector3f& head = build.landmarks.point("head_centre");
  std::vector<int> face;
  for (std::size_t t = 0; t < count.size(); ++t) {
    ASSERT_LE(count[t], 1) << "triangle " << t;
    if (count[t] == 1) continue;
    // Unlabelled: only the face in front of the ears, above the neck (cranial nerve V).
    const Eigen::Vector3f c = centroid(model.skin, static_cast<int>(t));
    ASSERT_GT(c.x(), head.x() - 0.01f) << "triangle " << t;
    ASSERT_GT(c.z(), build.landmarks.neck_z) << "triangle " << t;
    face.push_back(static_cast<int>(t));
  }
  EXPECT_FALSE(face.empty());
  // The face is about half the head, the head 9 % of the body surface (rule of nines).
  EXPECT_LT(trianglesArea(model.skin, face), 0.06 * trianglesArea(model.skin, [&] {
                                               std::vector<int> all(model.skin.triangles.size());
                                               std::iota(all.begin(), all.end(), 0);
                                               return all;
                                             }()));
  // Both perianal ids resolve, S5 innermost.
  EXPECT_NE(model.skinRegion("dermatome_S4", Side::kLeft), nullptr);
  EXPECT_NE(model.skinRegion("dermatome_S5", Side::kRight), nullptr);
  EXPECT_EQ(model.skinRegion("dermatome_C1", Side::kLeft), nullptr);
}

TEST(DermatomeLabellingTest, EveryKeySensoryPointLiesInItsOwnDermatome) {
  const AvatarBuild& build = defaultAvatar();
  const std::vector<int> label = labels(build.model);
  for (Side side : {Side::kLeft, Side::kRight}) {
    for (const std::string& level : dermatomeLevels()) {
      const Eigen::Vector3f& key = build.landmarks.point("key_" + level + "_" + toString(side));
      const SkinRegion& region =
          build.model.skin_regions[label[nearestTriangle(build.model.skin, key)]];
      EXPECT_EQ(region.structure_id, "dermatome_" + level) << toString(side);
      EXPECT_EQ(region.side, side) << level;
    }
  }
}

TEST(DermatomeLabellingTest, EachDermatomeIsOneConnectedRegion) {
  const AvatarModel& model = defaultAvatar().model;
  const std::vector<std::vector<int>> neighbours = triangleNeighbours(model.skin);
  const std::vector<int> label = labels(model);
  for (std::size_t r = 0; r < model.skin_regions.size(); ++r) {
    const std::vector<int>& triangles = model.skin_regions[r].triangles;
    std::set<int> reached = {triangles.front()};
    std::queue<int> open;
    open.push(triangles.front());
    while (!open.empty()) {
      const int t = open.front();
      open.pop();
      for (int n : neighbours[t]) {
        if (label[n] == static_cast<int>(r) && reached.insert(n).second) open.push(n);
      }
    }
    EXPECT_EQ(reached.size(), triangles.size()) << model.skin_regions[r].display_name;
  }
}

TEST(DermatomeLabellingTest, LeftAndRightAreMirrorImages) {
  const AvatarModel& model = defaultAvatar().model;
  const std::vector<int> label = labels(model);
  std::size_t checked = 0, matching = 0;
  for (std::size_t t = 0; t < model.skin.triangles.size(); t += 9) {
    if (label[t] < 0) continue;  // the face
    const SkinRegion& region = model.skin_regions[label[t]];
    Eigen::Vector3f mirrored = centroid(model.skin, static_cast<int>(t));
    mirrored.y() = -mirrored.y();
    const int image_label = label[nearestTriangle(model.skin, mirrored)];
    if (image_label < 0) continue;
    const SkinRegion& image = model.skin_regions[image_label];
    ++checked;
    matching +=
        image.structure_id == region.structure_id && image.side == contralateral(region.side);
  }
  EXPECT_GT(static_cast<double>(matching) / checked, 0.97) << matching << " of " << checked;
}

TEST(DermatomeLabellingTest, BandsAreOrderedAlongTheBody) {
  const AvatarBuild& build = defaultAvatar();
  const AvatarModel& model = build.model;
  for (Side side : {Side::kLeft, Side::kRight}) {
    // Trunk: C4, T2 ... T12 from the top down on the front of the chest and abdomen, and
    // T3 ... T12 on the back.
    const float sign = sideSign(side);
    const Eigen::AlignedBox3f front(Eigen::Vector3f(0.04f, std::min(0.0f, sign * 0.12f), 0),
                                    Eigen::Vector3f(1, std::max(0.0f, sign * 0.12f), 2));
    const Eigen::AlignedBox3f back(Eigen::Vector3f(-1, std::min(0.0f, sign * 0.12f), 0),
                                   Eigen::Vector3f(-0.04f, std::max(0.0f, sign * 0.12f), 2));
    EXPECT_GT(meanCentroid(model, "C4", side, front).z(),
              meanCentroid(model, "T2", side, front).z());
    for (int level = 3; level <= 12; ++level) {
      const std::string upper = "T" + std::to_string(level - 1),
                        lower = "T" + std::to_string(level);
      EXPECT_LT(meanCentroid(model, lower, side, front).z(),
                meanCentroid(model, upper, side, front).z())
          << lower << " front";
      if (level > 3) {
        EXPECT_LT(meanCentroid(model, lower, side, back).z(),
                  meanCentroid(model, upper, side, back).z())
            << lower << " back";
      }
    }
    // Front of the leg: L1 ... L4 downwards.
    for (const auto& [upper, lower] : {std::pair{"L1", "L2"}, {"L2", "L3"}, {"L3", "L4"}}) {
      EXPECT_GT(meanCentroid(model, upper, side).z(), meanCentroid(model, lower, side).z())
          << upper << " " << lower;
    }
    // Arm: C5 and T1 around the elbow, C6-C8 further out towards the hand.
    const Eigen::Vector3f& shoulder = build.landmarks.point("shoulder_" + toString(side));
    const auto reach = [&](const std::string& level) {
      return (meanCentroid(model, level, side) - shoulder).norm();
    };
    EXPECT_LT(reach("C4"), reach("C5"));
    EXPECT_LT(reach("C5"), reach("C6"));
    EXPECT_LT(reach("T1"), reach("C8"));
    EXPECT_LT(reach("T2"), reach("T1"));
  }
}

TEST(DermatomeLabellingTest, LabellingIsAFunctionOfTheMeshNotOfItsVertexOrder) {
  // The same skin with its triangles in reverse order labels the same surface the same way.
  const AvatarBuild& build = defaultAvatar();
  TriangleMesh reversed = build.model.skin;
  std::reverse(reversed.triangles.begin(), reversed.triangles.end());
  const std::vector<SkinRegion> regions =
      labelDermatomes(reversed, build.landmarks, test::catalog());
  const std::size_t count = build.model.skin.triangles.size();
  for (std::size_t r = 0; r < regions.size(); ++r) {
    std::set<int> original(build.model.skin_regions[r].triangles.begin(),
                           build.model.skin_regions[r].triangles.end());
    std::size_t same = 0;
    for (int t : regions[r].triangles) same += original.count(static_cast<int>(count - 1) - t);
    EXPECT_GT(same, 0.95 * original.size()) << regions[r].display_name;
  }
}

}  // namespace
}  // namespace vicc_anatomy_viz::avatar
