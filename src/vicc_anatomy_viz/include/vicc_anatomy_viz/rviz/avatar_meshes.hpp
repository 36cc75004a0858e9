#pragma once
// Avatar geometry -> OGRE manual objects (positions, normals, texture coordinates).

#include <string>
#include <vector>

#include <OGRE/OgreManualObject.h>

#include "vicc_anatomy_viz/avatar/avatar_model.hpp"

namespace vicc_anatomy_viz::rviz_plugin {

/// One section of `mesh`'s triangles (all of them when `triangles` is null), every vertex
/// moved `lift` metres along its normal (a skin region drawn just above the skin),
/// texture coordinates for `texture_frequency` cells per decimetre (0: none).
void addMeshSection(Ogre::ManualObject& object, const avatar::TriangleMesh& mesh,
                    const std::vector<int>* triangles, const std::string& material, float lift,
                    float texture_frequency);

/// A proxy disc lying on the skin, `lift` metres above it.
void addProxyDisc(Ogre::ManualObject& object, const avatar::SkinProxy& proxy,
                  const std::string& material, float lift, float texture_frequency);

/// Axis-aligned bounds of a mesh (min, max); false when it has no vertex.
bool meshBounds(const avatar::TriangleMesh& mesh, Eigen::Vector3f& min, Eigen::Vector3f& max);

}  // namespace vicc_anatomy_viz::rviz_plugin
