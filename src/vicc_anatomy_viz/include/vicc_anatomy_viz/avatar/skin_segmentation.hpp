#pragma once
// Limb segmentation of the skin: every vertex assigned to a body part and side, by cutting
// planes at the landmarks (crotch, armpit, elbow, wrist, knee, ankle, neck) and connected
// components of the mesh between them.

#include <vector>

#include "vicc_anatomy_viz/avatar/body_landmarks.hpp"

namespace vicc_anatomy_viz::avatar {

enum class BodyPart {
  kHead,
  kFace,
  kNeck,
  kTrunk,
  kUpperArm,
  kForearm,
  kHand,
  kThigh,
  kShank,
  kFoot
};

const char* toString(BodyPart part);

struct SkinSegmentation {
  std::vector<BodyPart> part;  ///< per skin vertex
  std::vector<Side> side;      ///< per skin vertex: left or right (the midline counts as left)
  std::vector<bool> midline;   ///< per skin vertex: on the midsagittal plane (|y| < 0.5 mm)
};

/// kFace is the trigeminal area (the head in front of the ears, above the jaw): no dermatome.
SkinSegmentation segmentSkin(const TriangleMesh& skin, const BodyLandmarks& landmarks);

}  // namespace vicc_anatomy_viz::avatar
