// Trunk surface points (umbilicus, nipple line) and the ISNCSCI key sensory points, placed on
// the skin by rays from the bone axes in anatomical directions (ISNCSCI 2019 worksheet).
#include <Eigen/Geometry>

#include <cmath>

#include "landmark_steps.hpp"
#include "vicc_anatomy_viz/errors.hpp"

namespace vicc_anatomy_viz::avatar::landmark_steps {

namespace {

/// The front of the trunk at height z and lateral offset y (ray forward from inside).
std::optional<float> frontX(const TriangleMesh& skin, float y, float z) {
  const std::vector<SectionLoop> loops = horizontalLoops(skin, z);
  const SectionLoop* trunk = midlineLoop(loops);
  if (!trunk) return std::nullopt;
  const Eigen::Vector2f inside(trunk->centroid.x(), y);
  if (!trunk->contains(inside)) return std::nullopt;
  const std::optional<float> distance = trunk->rayDistance(inside, Eigen::Vector2f::UnitX());
  if (!distance) return std::nullopt;
  return inside.x() + *distance;
}

/// The umbilicus: the deepest dent of the anterior midline between 55 % and 65 % of the height
/// (60 % when the mesh has no navel).
float umbilicusHeight(const TriangleMesh& skin, float height) {
  const float delta = 0.02f * height;
  float best_z = 0.60f * height, best_dent = 0.002f;
  for (float z = 0.55f * height; z <= 0.65f * height; z += 0.0025f * height) {
    const auto here = frontX(skin, 0, z), below = frontX(skin, 0, z - delta),
               above = frontX(skin, 0, z + delta);
    if (!here || !below || !above) continue;
    const float dent = (*below + *above) / 2 - *here;
    if (dent > best_dent) {
      best_dent = dent;
      best_z = z;
    }
  }
  return best_z;
}

/// The nipple line: the most anterior chest level between 66 % and 78 % of the height at the
/// midclavicular line (72 % on a flat chest).
float nippleHeight(const TriangleMesh& skin, float height, float y) {
  float best_z = 0.72f * height, lowest = 1e9f, highest = -1e9f;
  for (float z = 0.66f * height; z <= 0.78f * height; z += 0.0025f * height) {
    const auto front = frontX(skin, y, z);
    if (!front) continue;
    lowest = std::min(lowest, *front);
    if (*front > highest) {
      highest = *front;
      best_z = z;
    }
  }
  return highest - lowest > 0.003f ? best_z : 0.72f * height;
}

Eigen::Vector3f trunkFront(const TriangleMesh& skin, const BodyLandmarks& landmarks, float y,
                           float z, const std::string& what) {
  const Eigen::Vector3f origin(landmarks.point("pelvis").x(), y, z);
  return skinPointToward(skin, origin, Eigen::Vector3f::UnitX(), what);
}

/// A skin point seen from a bone: from the axis at `fraction` towards `azimuth`.
Eigen::Vector3f fromBone(const TriangleMesh& skin, const BodyLandmarks& landmarks,
                         const std::string& segment, Side side, float fraction, float azimuth,
                         const std::string& what) {
  const BoneFrame bone = landmarks.bone(segment, side);
  return skinPointToward(skin, bone.at(fraction), bone.direction(azimuth), what);
}

void placeArmPoints(const TriangleMesh& skin, Side side, BodyLandmarks& landmarks) {
  auto& p = landmarks.points;
  const auto key = [side](const std::string& level) { return sided("key_" + level, side); };
  const Eigen::Vector3f& shoulder = landmarks.point(sided("shoulder", side));
  p[key("C4")] = skinPointToward(
      skin, shoulder - sideSign(side) * 0.012f * landmarks.height * Eigen::Vector3f::UnitY(),
      Eigen::Vector3f::UnitZ(), key("C4"));
  p[key("C5")] = fromBone(skin, landmarks, "upper_arm", side, 0.93f, 60, key("C5"));
  p[key("T1")] = fromBone(skin, landmarks, "upper_arm", side, 0.93f, -60, key("T1"));
  // C6, C7, C8: the dorsal surface of the proximal phalanx of thumb, middle and little finger.
  const BoneFrame hand = landmarks.bone("hand", side);
  const Eigen::Vector3f dorsal = -hand.anterior;
  p[key("C6")] = skinPointToward(skin, landmarks.point(sided("thumb", side)), dorsal, key("C6"));
  p[key("C7")] = skinPointToward(skin, hand.at(0.62f), dorsal, key("C7"));
  p[key("C8")] =
      skinPointToward(skin, landmarks.point(sided("little_finger", side)), dorsal, key("C8"));
  p[key("T2")] = skinPointToward(skin, shoulder, -Eigen::Vector3f::UnitZ(), key("T2"));
}

void placeLegPoints(const TriangleMesh& skin, Side side, BodyLandmarks& landmarks) {
  auto& p = landmarks.points;
  const auto key = [side](const std::string& level) { return sided("key_" + level, side); };
  const float height = landmarks.height;
  p[key("L3")] = fromBone(skin, landmarks, "thigh", side, 0.9f, -90, key("L3"));
  const float l2_z = (p[key("T12")].z() + p[key("L3")].z()) / 2;
  const BoneFrame thigh = landmarks.bone("thigh", side);
  const float l2_fraction = (thigh.proximal.z() - l2_z) / (thigh.proximal.z() - thigh.distal.z());
  p[key("L2")] = fromBone(skin, landmarks, "thigh", side, l2_fraction, 0, key("L2"));
  const Eigen::Vector3f l1_target = (p[key("T12")] + p[key("L2")]) / 2;
  p[key("L1")] = skinPointToward(skin, thigh.proximal, l1_target - thigh.proximal, key("L1"));
  p[key("L4")] = fromBone(skin, landmarks, "shank", side, 1.0f, -90, key("L4"));
  p[key("L5")] = skinPointToward(skin, landmarks.point(sided("mtp", side)),
                                 Eigen::Vector3f::UnitZ(), key("L5"));
  const Eigen::Vector3f heel_inside =
      landmarks.point(sided("heel", side)) + Eigen::Vector3f(0.03f, 0, 0.02f * height);
  p[key("S1")] =
      skinPointToward(skin, heel_inside,
                      Eigen::Vector3f(-1, 0, 0) + landmarks.bone("shank", side).lateral, key("S1"));
  p[key("S2")] = fromBone(skin, landmarks, "thigh", side, 1.0f, 180, key("S2"));
  const Eigen::Vector3f& hip = landmarks.point(sided("hip", side));
  p[key("S3")] = skinPointToward(
      skin, Eigen::Vector3f(hip.x(), 0.5f * hip.y(), landmarks.crotch_z + 0.01f * height),
      -Eigen::Vector3f::UnitX(), key("S3"));
  // Perianal: S5 next to the anus, S4 a little further out (both ISNCSCI "S4-5").
  for (const auto& [level, offset] :
       {std::pair<std::string, float>{"S5", 0.004f}, std::pair<std::string, float>{"S4", 0.012f}}) {
    const Eigen::Vector3f inside(landmarks.point("pelvis").x(), sideSign(side) * offset * height,
                                 landmarks.crotch_z + 0.015f * height);
    p[key(level)] = skinPointToward(skin, inside, Eigen::Vector3f(-1, 0, -1), key(level));
  }
}

void placeTrunkPoints(const TriangleMesh& skin, Side side, BodyLandmarks& landmarks) {
  auto& p = landmarks.points;
  const auto key = [side](const std::string& level) { return sided("key_" + level, side); };
  const float height = landmarks.height, sign = sideSign(side);
  const Eigen::Vector3f& shoulder = landmarks.point(sided("shoulder", side));
  const float midclavicular = 0.5f * shoulder.y();
  const Eigen::Vector3f& head = landmarks.point("head_centre");
  p[key("C2")] = skinPointToward(skin, Eigen::Vector3f(head.x(), sign * 0.01f * height, head.z()),
                                 -Eigen::Vector3f::UnitX(), key("C2"));
  // The supraclavicular fossa: the top of the shoulder girdle just in front of the trapezius
  // at the midclavicular line, seen from inside the chest.
  const Eigen::Vector3f below_fossa(landmarks.point("pelvis").x() + 0.02f * height, midclavicular,
                                    shoulder.z());
  p[key("C3")] = skinPointToward(skin, below_fossa, Eigen::Vector3f::UnitZ(), key("C3"));
  const float nipple_z = nippleHeight(skin, height, midclavicular);
  const float umbilicus_z = landmarks.point("umbilicus").z();
  const float step = (nipple_z - umbilicus_z) / 6;
  p[key("T3")] = trunkFront(skin, landmarks, midclavicular, nipple_z + step, key("T3"));
  for (int level = 4; level <= 9; ++level) {
    const std::string name = "T" + std::to_string(level);
    p[key(name)] =
        trunkFront(skin, landmarks, midclavicular, nipple_z - (level - 4) * step, key(name));
  }
  p[key("T10")] = trunkFront(skin, landmarks, sign * 0.01f * height, umbilicus_z, key("T10"));
  const Eigen::Vector3f& hip = landmarks.point(sided("hip", side));
  p[key("T12")] = trunkFront(skin, landmarks, 0.5f * hip.y(), hip.z() + 0.01f * height, key("T12"));
  const Eigen::Vector3f t11 = (p[key("T10")] + p[key("T12")]) / 2;
  p[key("T11")] = trunkFront(skin, landmarks, t11.y(), t11.z(), key("T11"));
}

}  // namespace

void findTrunkPoints(const TriangleMesh& skin, BodyLandmarks& landmarks) {
  const float height = landmarks.height;
  const float head_z = height - 0.065f * height;
  const SectionLoop* head = nullptr;
  const std::vector<SectionLoop> loops = horizontalLoops(skin, head_z);
  head = midlineLoop(loops);
  if (!head) throw ConfigError("avatar landmarks: no head section");
  landmarks.points["head_centre"] = Eigen::Vector3f(head->centroid.x(), head->centroid.y(), head_z);
  const float umbilicus_z = umbilicusHeight(skin, height);
  landmarks.points["umbilicus"] = trunkFront(skin, landmarks, 0, umbilicus_z, "umbilicus");
}

void placeKeySensoryPoints(const TriangleMesh& skin, BodyLandmarks& landmarks) {
  for (Side side : {Side::kLeft, Side::kRight}) {
    placeArmPoints(skin, side, landmarks);
    placeTrunkPoints(skin, side, landmarks);
    placeLegPoints(skin, side, landmarks);
  }
}

}  // namespace vicc_anatomy_viz::avatar::landmark_steps
