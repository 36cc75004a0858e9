#pragma once
// Landmarks of a skin mesh in REP-103, estimated from its cross-sections: joint centres, bone
// axes (limb centre lines) and the ISNCSCI key sensory points on the skin. Method in
// docs/avatar_model.md ("Landmarks").

#include <Eigen/Core>

#include <array>
#include <map>
#include <string>
#include <vector>

#include "vicc_anatomy_viz/anatomy_catalog.hpp"
#include "vicc_anatomy_viz/avatar/avatar_model.hpp"

namespace vicc_anatomy_viz::avatar {

/// A limb's centre line from proximal to distal: the centroids of its cross-sections.
struct LimbTrack {
  std::vector<Eigen::Vector3f> centres;
  std::vector<float> areas;       ///< cross-section area at each centre, m^2
  std::vector<float> arc_length;  ///< from the first centre, m
};

/// 0 for the left side, 1 for the right (kNone is not a limb side).
int sideIndex(Side side);
/// +1 for left (REP-103 y points left), -1 for right.
float sideSign(Side side);

/// An orthonormal frame along a bone: axis from proximal to distal joint, anterior, lateral
/// (away from the midline). Azimuth 0 is anterior, +90 degrees lateral.
struct BoneFrame {
  Eigen::Vector3f proximal = Eigen::Vector3f::Zero();
  Eigen::Vector3f distal = Eigen::Vector3f::Zero();
  Eigen::Vector3f axis = Eigen::Vector3f::UnitZ();
  Eigen::Vector3f anterior = Eigen::Vector3f::UnitX();
  Eigen::Vector3f lateral = Eigen::Vector3f::UnitY();
  float length() const { return (distal - proximal).norm(); }
  Eigen::Vector3f at(float fraction) const { return proximal + fraction * (distal - proximal); }
  Eigen::Vector3f direction(float azimuth_degrees) const;
};

struct BodyLandmarks {
  float height = 0;    ///< m, top of the head
  float crotch_z = 0;  ///< lowest point where the legs join
  float armpit_z = 0;  ///< highest level at which the arms are apart from the trunk
  float neck_z = 0;    ///< narrowest section of the neck
  /// Joint centres and skin points by name, e.g. "elbow_left", "key_C5_right", "umbilicus".
  std::map<std::string, Eigen::Vector3f> points;
  std::array<LimbTrack, 2> arm_tracks;  ///< shoulder region to fingertip, by sideIndex
  std::array<LimbTrack, 2> leg_tracks;  ///< ankle to crotch (distal to proximal), by sideIndex

  /// The named point; throws ConfigError naming it when the landmarks have none.
  const Eigen::Vector3f& point(const std::string& name) const;
  /// The frame of a bone segment on a side: upper_arm, forearm, hand, thigh, shank, foot,
  /// trunk (pelvis to neck), head.
  BoneFrame bone(const std::string& segment, Side side) const;
};

/// Estimates the landmarks of a skin in REP-103 standing upright with the arms apart from the
/// trunk and the legs apart (A- or T-pose). Throws ConfigError when a step finds no section
/// it needs (e.g. the legs touch, no arm apart from the trunk).
BodyLandmarks estimateLandmarks(const TriangleMesh& skin);

}  // namespace vicc_anatomy_viz::avatar
