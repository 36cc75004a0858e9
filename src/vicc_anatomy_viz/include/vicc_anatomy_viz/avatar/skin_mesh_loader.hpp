#pragma once
// Loads the skin (and atlas) meshes with assimp and converts it once to REP-103 (x forward, y left,
// z up, metres, feet at z = 0, the body's centre of volume above the origin).

#include <string>

#include "vicc_anatomy_viz/avatar/avatar_manifest.hpp"
#include "vicc_anatomy_viz/avatar/avatar_model.hpp"

namespace vicc_anatomy_viz::avatar {

/// Reads, merges duplicate vertices, converts to REP-103, orients the triangles outwards and
/// computes vertex normals. Throws ConfigError naming the file when it is missing or
/// unreadable, has no such mesh, or is not a closed surface; and when the axes are not two
/// different signed axes ("+x", "-z", ...).
TriangleMesh loadSkinMesh(const MeshSource& source);

/// An atlas structure mesh (e.g. a BodyParts3D OBJ): rotated, scaled and translated as the
/// source says, duplicate vertices merged, normals computed; need not be closed.
TriangleMesh loadAtlasMesh(const MeshSource& source);

}  // namespace vicc_anatomy_viz::avatar
