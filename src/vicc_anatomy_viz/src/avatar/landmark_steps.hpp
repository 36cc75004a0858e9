#pragma once
// The steps of estimateLandmarks, each filling its part of BodyLandmarks (internal).

#include <string>
#include <vector>

#include "vicc_anatomy_viz/avatar/body_landmarks.hpp"
#include "vicc_anatomy_viz/avatar/cross_section.hpp"

namespace vicc_anatomy_viz::avatar::landmark_steps {

/// Loops of the horizontal section at height z, in (x, y) coordinates.
std::vector<SectionLoop> horizontalLoops(const TriangleMesh& skin, float z);
/// The loop of a horizontal section that straddles the midsagittal plane (trunk, neck, head)
/// with the largest area, or nullptr.
const SectionLoop* midlineLoop(const std::vector<SectionLoop>& loops);

/// The first skin point hit from `origin` (inside the body) along `direction`; ConfigError
/// naming `what` if the ray leaves without a hit.
Eigen::Vector3f skinPointToward(const TriangleMesh& skin, const Eigen::Vector3f& origin,
                                const Eigen::Vector3f& direction, const std::string& what);

void findTrunkLevels(const TriangleMesh& skin, BodyLandmarks& landmarks);
void findLegJoints(const TriangleMesh& skin, BodyLandmarks& landmarks);
void findArmJoints(const TriangleMesh& skin, BodyLandmarks& landmarks);
void findTrunkPoints(const TriangleMesh& skin, BodyLandmarks& landmarks);
void placeKeySensoryPoints(const TriangleMesh& skin, BodyLandmarks& landmarks);

/// "elbow" + left -> "elbow_left".
std::string sided(const std::string& name, Side side);

}  // namespace vicc_anatomy_viz::avatar::landmark_steps
