#pragma once
// The avatar manifest (config/anatomy/avatar.yaml): which skin mesh, which structures (generated
// from the skin's landmarks or read from atlas mesh files) with sides and a place in the
// hierarchy, and how the skin is labelled. Format in docs/avatar_model.md.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "vicc_anatomy_viz/anatomy_catalog.hpp"

namespace vicc_anatomy_viz::avatar {

/// A mesh file and how its axes and units map onto REP-103.
struct MeshSource {
  std::string path;       ///< resolved against the manifest's directory
  std::string mesh_name;  ///< the mesh of the file to use; "" = all meshes
  std::string up_axis = "+y";
  std::string forward_axis = "+z";
  float unit_in_metres = 1.0f;
  std::array<float, 3> translation = {0, 0, 0};  ///< added after rotation and scaling, m
};

/// A structure generated around a bone axis: a spindle from `from` to `to` (fractions of the
/// bone from its proximal joint), its centre `depth` of the way from the axis to the skin
/// towards `azimuth` (degrees, 0 anterior, +90 lateral), its radial half-thickness
/// `thickness` times the skin radius there, its tangential half-width `width` times that.
struct GeneratedShape {
  std::string bone;
  float from = 0, to = 1;
  float azimuth = 0;
  float depth = 0.5f;
  float thickness = 0.3f;
  float width = 1.0f;
};

/// Where a proxy sits: the skin point hit from the bone axis at `at` towards `azimuth`,
/// tilted by `elevation` degrees towards the distal end of the bone.
struct ProxyPlacement {
  std::string bone;
  float at = 0.5f;
  float azimuth = 0;
  float elevation = 0;
  float radius = 0.02f;  ///< m
};

struct StructureEntry {
  std::string id;
  std::vector<Side> sides;
  std::string region;  ///< e.g. "upper limb"
  std::string system;  ///< e.g. "muscular system"
  std::string fma_id;  ///< the catalogue's, checked against the manifest's if it gives one
  /// Generated parts (empty: none), e.g. a muscle belly on the shank and its tendon over the
  /// foot; the structure's mesh is their union.
  std::vector<GeneratedShape> generated;
  std::optional<MeshSource> mesh;  ///< an atlas mesh instead of a generated shape
  std::optional<ProxyPlacement> proxy;
  std::string where;  ///< "file:line: structures[i]" for messages
};

struct AvatarManifest {
  std::string path;
  MeshSource skin;
  std::string skin_labelling = "dermatomes";  ///< the only labelling so far
  std::vector<StructureEntry> structures;
};

/// Reads and checks the manifest against the catalogue (unknown structure ids, sides the
/// structure does not have, FMA ids that differ from the catalogue's, misspelt keys): throws
/// ConfigError naming the file, line and entry.
AvatarManifest loadAvatarManifest(const std::string& path, const AnatomyCatalog& catalog);

}  // namespace vicc_anatomy_viz::avatar
