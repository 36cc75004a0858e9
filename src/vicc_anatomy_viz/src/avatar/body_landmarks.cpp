#include "vicc_anatomy_viz/avatar/body_landmarks.hpp"

#include <Eigen/Geometry>

#include <cmath>

#include "landmark_steps.hpp"
#include "vicc_anatomy_viz/avatar/mesh_geometry.hpp"
#include "vicc_anatomy_viz/errors.hpp"

namespace vicc_anatomy_viz::avatar {

namespace landmark_steps {

std::vector<SectionLoop> horizontalLoops(const TriangleMesh& skin, float z) {
  return sliceMesh(skin, SectionPlane::through(Eigen::Vector3f(0, 0, z), Eigen::Vector3f::UnitZ(),
                                               Eigen::Vector3f::UnitX()));
}

const SectionLoop* midlineLoop(const std::vector<SectionLoop>& loops) {
  const SectionLoop* best = nullptr;
  for (const SectionLoop& loop : loops) {
    if (loop.min_corner.y() < 0 && loop.max_corner.y() > 0 && (!best || loop.area > best->area)) {
      best = &loop;
    }
  }
  return best;
}

Eigen::Vector3f skinPointToward(const TriangleMesh& skin, const Eigen::Vector3f& origin,
                                const Eigen::Vector3f& direction, const std::string& what) {
  const std::optional<Eigen::Vector3f> hit = castRay(skin, origin, direction);
  if (!hit) throw ConfigError("avatar landmarks: no skin found for " + what);
  return *hit;
}

std::string sided(const std::string& name, Side side) { return name + "_" + toString(side); }

}  // namespace landmark_steps

int sideIndex(Side side) { return side == Side::kRight ? 1 : 0; }
float sideSign(Side side) { return side == Side::kRight ? -1.0f : 1.0f; }

Eigen::Vector3f BoneFrame::direction(float azimuth_degrees) const {
  const float radians = azimuth_degrees * static_cast<float>(M_PI) / 180.0f;
  return std::cos(radians) * anterior + std::sin(radians) * lateral;
}

const Eigen::Vector3f& BodyLandmarks::point(const std::string& name) const {
  const auto found = points.find(name);
  if (found == points.end()) throw ConfigError("avatar landmarks: no landmark '" + name + "'");
  return found->second;
}

BodyLandmarks estimateLandmarks(const TriangleMesh& skin) {
  using namespace landmark_steps;
  BodyLandmarks landmarks;
  for (const Eigen::Vector3f& vertex : skin.vertices) {
    landmarks.height = std::max(landmarks.height, vertex.z());
  }
  findTrunkLevels(skin, landmarks);
  findLegJoints(skin, landmarks);
  findArmJoints(skin, landmarks);
  findTrunkPoints(skin, landmarks);
  placeKeySensoryPoints(skin, landmarks);
  return landmarks;
}

}  // namespace vicc_anatomy_viz::avatar
