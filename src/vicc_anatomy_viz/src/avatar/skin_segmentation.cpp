#include "vicc_anatomy_viz/avatar/skin_segmentation.hpp"

#include <cmath>
#include <queue>

#include "vicc_anatomy_viz/avatar/mesh_geometry.hpp"

namespace vicc_anatomy_viz::avatar {

namespace {

// The leg's upper boundary rises laterally from the crotch (the inguinal ligament and the
// gluteal fold run obliquely), by tan 20 degrees.
constexpr float kLegBoundarySlope = 0.36f;

/// Marks `part` on the connected set of `candidate` vertices that contains `start`.
void floodFill(const VertexGraph& graph, const std::vector<bool>& candidate, int start,
               std::vector<bool>& member) {
  member.assign(graph.size(), false);
  if (start < 0 || !candidate[start]) return;
  std::queue<int> open;
  open.push(start);
  member[start] = true;
  while (!open.empty()) {
    const int vertex = open.front();
    open.pop();
    for (const auto& [neighbour, length] : graph[vertex]) {
      if (candidate[neighbour] && !member[neighbour]) {
        member[neighbour] = true;
        open.push(neighbour);
      }
    }
  }
}

void segmentLeg(const TriangleMesh& skin, const VertexGraph& graph, const BodyLandmarks& landmarks,
                Side side, SkinSegmentation& segmentation) {
  const float sign = sideSign(side);
  std::vector<bool> candidate(skin.vertices.size());
  for (std::size_t i = 0; i < skin.vertices.size(); ++i) {
    const Eigen::Vector3f& v = skin.vertices[i];
    candidate[i] =
        v.y() * sign > 0 && v.z() < landmarks.crotch_z + kLegBoundarySlope * std::abs(v.y());
  }
  std::vector<bool> leg;
  floodFill(graph, candidate, nearestVertex(skin, landmarks.point("ankle_" + toString(side))), leg);
  const float knee_z = landmarks.point("knee_" + toString(side)).z();
  const float ankle_z = landmarks.point("ankle_" + toString(side)).z();
  for (std::size_t i = 0; i < skin.vertices.size(); ++i) {
    if (!leg[i]) continue;
    const float z = skin.vertices[i].z();
    segmentation.part[i] = z >= knee_z    ? BodyPart::kThigh
                           : z >= ankle_z ? BodyPart::kShank
                                          : BodyPart::kFoot;
  }
}

void segmentArm(const TriangleMesh& skin, const VertexGraph& graph, const BodyLandmarks& landmarks,
                Side side, SkinSegmentation& segmentation) {
  const BoneFrame upper = landmarks.bone("upper_arm", side);
  const BoneFrame forearm = landmarks.bone("forearm", side);
  const BoneFrame hand = landmarks.bone("hand", side);
  // The arm starts at the plane across the upper arm through the apex of the axilla.
  const float start =
      (landmarks.point("key_T2_" + toString(side)) - upper.proximal).dot(upper.axis);
  std::vector<bool> candidate(skin.vertices.size());
  for (std::size_t i = 0; i < skin.vertices.size(); ++i) {
    candidate[i] = (skin.vertices[i] - upper.proximal).dot(upper.axis) > start &&
                   segmentation.part[i] == BodyPart::kTrunk;
  }
  std::vector<bool> arm;
  floodFill(graph, candidate, nearestVertex(skin, forearm.proximal), arm);
  const Eigen::Vector3f elbow_normal = (upper.axis + forearm.axis).normalized();
  const Eigen::Vector3f wrist_normal = (forearm.axis + hand.axis).normalized();
  for (std::size_t i = 0; i < skin.vertices.size(); ++i) {
    if (!arm[i]) continue;
    const Eigen::Vector3f& v = skin.vertices[i];
    segmentation.part[i] = (v - forearm.proximal).dot(elbow_normal) < 0 ? BodyPart::kUpperArm
                           : (v - hand.proximal).dot(wrist_normal) < 0  ? BodyPart::kForearm
                                                                        : BodyPart::kHand;
  }
}

}  // namespace

const char* toString(BodyPart part) {
  static const char* const names[] = {"head",    "face", "neck",  "trunk", "upper arm",
                                      "forearm", "hand", "thigh", "shank", "foot"};
  return names[static_cast<int>(part)];
}

SkinSegmentation segmentSkin(const TriangleMesh& skin, const BodyLandmarks& landmarks) {
  SkinSegmentation segmentation;
  segmentation.part.assign(skin.vertices.size(), BodyPart::kTrunk);
  segmentation.side.resize(skin.vertices.size());
  segmentation.midline.resize(skin.vertices.size());
  const VertexGraph graph = vertexGraph(skin);
  for (Side side : {Side::kLeft, Side::kRight})
    segmentLeg(skin, graph, landmarks, side, segmentation);
  for (Side side : {Side::kLeft, Side::kRight})
    segmentArm(skin, graph, landmarks, side, segmentation);
  const float height = landmarks.height;
  const float head_z = landmarks.neck_z + 0.015f * height;
  const float neck_z = landmarks.point("key_C4_left").z();
  const float ear_x = landmarks.point("head_centre").x();
  for (std::size_t i = 0; i < skin.vertices.size(); ++i) {
    const Eigen::Vector3f& v = skin.vertices[i];
    segmentation.side[i] = v.y() >= 0 ? Side::kLeft : Side::kRight;
    segmentation.midline[i] = std::abs(v.y()) < 5e-4f;
    if (segmentation.part[i] != BodyPart::kTrunk) continue;
    if (v.z() > head_z) {
      segmentation.part[i] = v.x() > ear_x ? BodyPart::kFace : BodyPart::kHead;
    } else if (v.z() > neck_z) {
      segmentation.part[i] = BodyPart::kNeck;
    }
  }
  return segmentation;
}

}  // namespace vicc_anatomy_viz::avatar
