#pragma once
// Text report and PLY export of a built avatar (vicc_avatar_model).

#include <ostream>
#include <string>

#include "vicc_anatomy_viz/avatar/avatar_builder.hpp"

namespace vicc_anatomy_viz::avatar {

/// Counts, build times, landmarks, per structure its vertex count and volume, per region its
/// triangle count and area.
void writeReport(const AvatarBuild& build, std::ostream& out);

/// One binary-free ASCII PLY per structure and per skin region (plus skin.ply) into
/// `directory` (created); returns the number of files. Throws ConfigError if unwritable.
std::size_t exportPly(const AvatarModel& model, const std::string& directory);

/// The region's triangles as a mesh of their own (vertices renumbered).
TriangleMesh regionMesh(const TriangleMesh& skin, const SkinRegion& region);

/// Surface area in m^2 of the listed triangles.
double trianglesArea(const TriangleMesh& mesh, const std::vector<int>& triangles);

}  // namespace vicc_anatomy_viz::avatar
