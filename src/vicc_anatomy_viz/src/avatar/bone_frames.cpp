// Bone frames from joint centres. "Anterior" follows the anatomical position: with the elbow
// bent, the front of the upper arm faces the forearm and the front of the forearm faces the
// upper arm; otherwise it is the body's forward direction made perpendicular to the bone.
#include <Eigen/Geometry>

#include <cmath>

#include "landmark_steps.hpp"
#include "vicc_anatomy_viz/avatar/body_landmarks.hpp"
#include "vicc_anatomy_viz/errors.hpp"

namespace vicc_anatomy_viz::avatar {

namespace {

using landmark_steps::sided;

constexpr float kBentElbowCosine = 0.966f;  // cos 15 degrees

Eigen::Vector3f perpendicular(const Eigen::Vector3f& vector, const Eigen::Vector3f& axis) {
  return vector - vector.dot(axis) * axis;
}

BoneFrame frame(const Eigen::Vector3f& proximal, const Eigen::Vector3f& distal,
                const Eigen::Vector3f& preferred_anterior, Side side) {
  BoneFrame bone;
  bone.proximal = proximal;
  bone.distal = distal;
  bone.axis = (distal - proximal).normalized();
  Eigen::Vector3f anterior = perpendicular(preferred_anterior, bone.axis);
  if (anterior.norm() < 1e-3f) anterior = perpendicular(Eigen::Vector3f::UnitX(), bone.axis);
  bone.anterior = anterior.normalized();
  bone.lateral = bone.axis.cross(bone.anterior).normalized();
  if (bone.lateral.y() * sideSign(side) < 0) bone.lateral = -bone.lateral;
  return bone;
}

/// The hand as in the anatomical position: lateral is the thumb's (radial) side, anterior the
/// palm, which for a left hand is axis x radial (right: the opposite), whatever the pose.
BoneFrame handFrame(const Eigen::Vector3f& wrist, const Eigen::Vector3f& fingertip,
                    const Eigen::Vector3f& thumb, Side side) {
  BoneFrame bone;
  bone.proximal = wrist;
  bone.distal = fingertip;
  bone.axis = (fingertip - wrist).normalized();
  bone.lateral = perpendicular(thumb - wrist, bone.axis).normalized();
  bone.anterior = (sideSign(side) * bone.axis.cross(bone.lateral)).normalized();
  return bone;
}

}  // namespace

BoneFrame BodyLandmarks::bone(const std::string& segment, Side side) const {
  const Eigen::Vector3f forward = Eigen::Vector3f::UnitX();
  if (segment == "trunk") return frame(point("pelvis"), point("neck"), forward, side);
  if (segment == "head") {
    const Eigen::Vector3f& neck = point("neck");
    return frame(neck, Eigen::Vector3f(neck.x(), neck.y(), height), forward, side);
  }
  if (segment == "thigh")
    return frame(point(sided("hip", side)), point(sided("knee", side)), forward, side);
  if (segment == "shank") {
    return frame(point(sided("knee", side)), point(sided("ankle", side)), forward, side);
  }
  if (segment == "foot") {
    return frame(point(sided("ankle", side)), point(sided("mtp", side)), Eigen::Vector3f::UnitZ(),
                 side);
  }
  const Eigen::Vector3f& shoulder = point(sided("shoulder", side));
  const Eigen::Vector3f& elbow = point(sided("elbow", side));
  const Eigen::Vector3f& wrist = point(sided("wrist", side));
  const bool bent =
      (elbow - shoulder).normalized().dot((wrist - elbow).normalized()) < kBentElbowCosine;
  if (segment == "upper_arm") {
    return frame(shoulder, elbow, bent ? Eigen::Vector3f(wrist - elbow) : forward, side);
  }
  if (segment == "forearm") {
    return frame(elbow, wrist, bent ? Eigen::Vector3f(shoulder - elbow) : forward, side);
  }
  if (segment == "hand")
    return handFrame(wrist, point(sided("fingertip", side)), point(sided("thumb", side)), side);
  throw ConfigError("avatar landmarks: unknown bone segment '" + segment + "'");
}

}  // namespace vicc_anatomy_viz::avatar
