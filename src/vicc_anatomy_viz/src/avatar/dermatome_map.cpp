#include "dermatome_map.hpp"

#include <Eigen/Geometry>

#include <cmath>

#include "landmark_steps.hpp"
#include "vicc_anatomy_viz/avatar/mesh_geometry.hpp"

namespace vicc_anatomy_viz::avatar::dermatome_map {

namespace {

using P = BodyPart;
constexpr int kSamplesPerAxis = 6;
constexpr int kRingSamples = 37;  // every 5 degrees from the front midline to the spine
constexpr float kRingDropStep = 0.005f;
constexpr int kBridgeSamples = 6;
constexpr float kRingMaxDropUnderAxilla = 0.08f;
// Thoracic bands rise towards the spine (the spinous processes lie above their ribs' front).
constexpr float kRingRiseTowardsSpine = 0.03f;

/// A skin point seen from the bone axis. On the forearm the direction turns from the elbow's
/// frame into the hand's (pronation moves the radius round the ulna).
std::optional<Eigen::Vector3f> axisPoint(const TriangleGrid& grid, const BodyLandmarks& landmarks,
                                         const std::string& segment, Side side, float fraction,
                                         float azimuth) {
  const BoneFrame bone = landmarks.bone(segment, side);
  Eigen::Vector3f direction = bone.direction(azimuth);
  if (segment == "forearm") {
    const float t = std::clamp(fraction, 0.0f, 1.0f);
    direction = (1 - t) * direction + t * landmarks.bone("hand", side).direction(azimuth);
    direction -= direction.dot(bone.axis) * bone.axis;
  }
  return grid.castRay(bone.at(fraction), direction);
}

/// The half ring of a trunk level: from the front midline round the side to the spine.
bool onTrunk(const TriangleMesh& skin, const TriangleGrid& grid,
             const SkinSegmentation& segmentation, const Eigen::Vector3f& point) {
  const BodyPart part = segmentation.part[skin.triangles[grid.nearestTriangle(point)][0]];
  return part == BodyPart::kTrunk || part == BodyPart::kNeck || part == BodyPart::kHead;
}

/// The half ring of a trunk level: from the front midline round the side to the spine. A ray
/// that meets the arm is lowered (at most `max_drop`) until it meets the chest wall.
std::vector<Eigen::Vector3f> ringSeeds(const TriangleMesh& skin, const TriangleGrid& grid,
                                       const BodyLandmarks& landmarks,
                                       const SkinSegmentation& segmentation, float front_z,
                                       Side side, float max_drop) {
  std::vector<Eigen::Vector3f> seeds;
  const std::vector<SectionLoop> loops = landmark_steps::horizontalLoops(skin, front_z);
  const SectionLoop* trunk = landmark_steps::midlineLoop(loops);
  if (!trunk) return seeds;
  for (int k = 0; k < kRingSamples; ++k) {
    const float angle = static_cast<float>(M_PI) * k / (kRingSamples - 1);
    const float rise = kRingRiseTowardsSpine * landmarks.height * (1 - std::cos(angle)) / 2;
    // Just beside the midline, so that the seed is on its own side.
    const float y = sideSign(side) * std::max(0.02f, std::sin(angle));
    const Eigen::Vector3f direction(std::cos(angle), y, 0);
    for (float drop = 0; drop <= max_drop; drop += kRingDropStep) {
      const Eigen::Vector3f origin(trunk->centroid.x(), 0, front_z + rise - drop);
      const std::optional<Eigen::Vector3f> hit = grid.castRay(origin, direction);
      if (hit && onTrunk(skin, grid, segmentation, *hit)) {
        seeds.push_back(*hit);
        break;
      }
    }
  }
  return seeds;
}

/// Seeds on the straight lines from `key` to the nearest of seeds[from...] in front of it and
/// to the nearest behind it (the labelling puts each on the skin triangle nearest to it).
void addBridges(const Eigen::Vector3f& key, std::vector<Eigen::Vector3f>& seeds, std::size_t from) {
  const std::size_t end = seeds.size();
  for (const bool in_front : {true, false}) {
    const Eigen::Vector3f* nearest = nullptr;
    for (std::size_t k = from; k < end; ++k) {
      if ((seeds[k].x() > key.x()) != in_front) continue;
      if (!nearest || (seeds[k] - key).norm() < (*nearest - key).norm()) nearest = &seeds[k];
    }
    if (!nearest) continue;
    const Eigen::Vector3f target = *nearest;
    for (int k = 1; k < kBridgeSamples; ++k) {
      seeds.push_back(key + (target - key) * (static_cast<float>(k) / kBridgeSamples));
    }
  }
}

/// The front height of a level's ring: the key point's, except where the key point is not on
/// the band's front (C2 occiput, C3 supraclavicular, C4 acromion, T2 axilla, L1 groin).
float ringHeight(const BodyLandmarks& landmarks, const std::string& level, Side side) {
  const auto key_z = [&](const std::string& name) {
    return landmarks.point("key_" + name + "_" + toString(side)).z();
  };
  const float step = key_z("T3") - key_z("T4");
  if (level == "C2") return landmarks.neck_z + 0.01f * landmarks.height;
  if (level == "C3") return (landmarks.neck_z + key_z("C3")) / 2;
  if (level == "C4") return key_z("T3") + 2 * step;
  if (level == "T2") return key_z("T3") + step;
  if (level == "L1") return (key_z("T12") + key_z("L1")) / 2;
  return key_z(level);
}

}  // namespace

const std::vector<LevelMap>& levels() {
  static const std::vector<LevelMap> map = {
      {"C2", {P::kHead, P::kNeck}, {}, true, 0},
      {"C3", {P::kNeck, P::kHead, P::kTrunk}, {}, true, 0},
      {"C4", {P::kNeck, P::kTrunk, P::kUpperArm}, {{"upper_arm", -0.15f, 0.1f, 90, 90}}, true, 0},
      {"C5", {P::kUpperArm, P::kForearm, P::kTrunk}, {{"upper_arm", 0.2f, 1.0f, 90, 60}}, false, 0},
      {"C6",
       {P::kForearm, P::kHand, P::kUpperArm},
       {{"forearm", 0.1f, 1.0f, 80, 90}, {"hand", 0.0f, 0.3f, 90, 90}},
       false,
       0},
      {"C7",
       {P::kForearm, P::kHand},
       {{"forearm", 0.4f, 1.0f, 180, 180},
        {"hand", 0.2f, 0.9f, 180, 180},
        {"hand", 0.2f, 0.9f, 0, 0}},
       false,
       0},
      {"C8",
       {P::kForearm, P::kHand},
       {{"forearm", 0.45f, 1.0f, -90, -90}, {"hand", 0.2f, 0.9f, -90, -90}},
       false,
       0},
      {"T1",
       {P::kForearm, P::kUpperArm},
       {{"forearm", 0.0f, 0.35f, -80, -90}, {"upper_arm", 0.6f, 1.0f, -90, -90}},
       false,
       0},
      {"T2", {P::kUpperArm, P::kTrunk}, {{"upper_arm", 0.1f, 0.55f, -90, -90}}, true, 0},
      {"T3", {P::kTrunk}, {}, true, 0, true},
      {"T4", {P::kTrunk}, {}, true, 0, true},
      {"T5", {P::kTrunk}, {}, true, 0, true},
      {"T6", {P::kTrunk}, {}, true, 0, true},
      {"T7", {P::kTrunk}, {}, true, 0, true},
      {"T8", {P::kTrunk}, {}, true, 0, true},
      {"T9", {P::kTrunk}, {}, true, 0, true},
      {"T10", {P::kTrunk}, {}, true, 0, true},
      {"T11", {P::kTrunk}, {}, true, 0, true},
      {"T12", {P::kTrunk}, {}, true, 0, true},
      {"L1", {P::kTrunk, P::kThigh}, {{"thigh", 0.0f, 0.1f, 30, -30}}, true, 0},
      {"L2", {P::kThigh, P::kTrunk}, {{"thigh", 0.15f, 0.55f, 60, -30}}, false, 0},
      {"L3", {P::kThigh, P::kShank}, {{"thigh", 0.55f, 0.95f, 20, -80}}, false, 0},
      {"L4",
       {P::kShank, P::kFoot, P::kThigh},
       {{"shank", 0.05f, 1.0f, -45, -90}, {"foot", 0.0f, 0.9f, -90, -90}},
       false,
       0},
      {"L5",
       {P::kShank, P::kFoot},
       {{"shank", 0.1f, 0.9f, 60, 45}, {"foot", 0.2f, 1.2f, 0, 0}},
       false,
       0},
      {"S1",
       {P::kShank, P::kFoot},
       {{"shank", 0.55f, 1.0f, 150, 150},
        {"foot", -0.2f, 1.0f, 90, 90},
        {"foot", -0.2f, 0.9f, 180, 180}},
       false,
       0},
      {"S2",
       {P::kThigh, P::kShank, P::kTrunk},
       {{"thigh", 0.1f, 1.0f, 180, 180}, {"shank", 0.0f, 0.45f, 180, -160}},
       false,
       0},
      {"S3", {P::kTrunk, P::kThigh}, {}, false, 0},
      // Perianal: S5 the innermost ring round the anus, S4 round it (both ISNCSCI "S4-5").
      {"S4", {P::kTrunk, P::kThigh}, {}, false, 0.045f},
      {"S5", {P::kTrunk, P::kThigh}, {}, false, 0.02f},
  };
  return map;
}

std::vector<Eigen::Vector3f> seedPoints(const TriangleMesh& skin, const TriangleGrid& grid,
                                        const BodyLandmarks& landmarks,
                                        const SkinSegmentation& segmentation, const LevelMap& level,
                                        Side side) {
  const Eigen::Vector3f key = landmarks.point("key_" + level.level + "_" + toString(side));
  std::vector<Eigen::Vector3f> seeds = {key};
  for (const BandAxis& axis : level.axes) {
    for (int k = 0; k < kSamplesPerAxis; ++k) {
      const float t = static_cast<float>(k) / (kSamplesPerAxis - 1);
      const float fraction = axis.from + t * (axis.to - axis.from);
      const float azimuth = axis.azimuth_from + t * (axis.azimuth_to - axis.azimuth_from);
      if (const auto hit = axisPoint(grid, landmarks, axis.segment, side, fraction, azimuth)) {
        seeds.push_back(*hit);
      }
    }
  }
  if (level.trunk_ring) {
    const std::vector<Eigen::Vector3f> ring =
        ringSeeds(skin, grid, landmarks, segmentation, ringHeight(landmarks, level.level, side),
                  side, level.ring_under_axilla ? kRingMaxDropUnderAxilla : 0.0f);
    const std::size_t ring_start = seeds.size();
    seeds.insert(seeds.end(), ring.begin(), ring.end());
    // A key point off its ring (occiput, acromion, axilla, groin) is joined to the ring's
    // front and back by lines of seeds, so that the band reaches it.
    addBridges(key, seeds, ring_start);
  }
  return seeds;
}

}  // namespace vicc_anatomy_viz::avatar::dermatome_map
