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

/// The cross-section of a generated structure at each station along its bone.
enum class SectionShape {
  /// An ellipse centred `depth` of the way from the axis to the skin towards `azimuth`, radial
  /// half-thickness `thickness` times that skin distance, tangential half-width `width` times
  /// the radial one (slender structures: tendons, small or deep muscles).
  kEllipse,
  /// A muscle belly filling its sector of the limb: the angles `azimuth` +- `span` / 2 around
  /// the bone axis, radially from `inner` to `outer` times the axis-to-skin distance in each
  /// direction, so its cross-section follows the limb's cross-section at that height.
  kSector,
  /// An organ filling a cavity: the skin's cross-section shrunk by `inset` metres (scalp and
  /// skull for the brain), optionally one half of it (`half`: a hemisphere on the body's left
  /// or right of the midsagittal plane, `fissure` metres between the two).
  kCavity,
};

/// A structure generated around a bone axis: swept from `from` to `to` (fractions of the bone
/// from its proximal joint), at each station its `section` in the plane perpendicular to the
/// bone, scaled towards its centre by the belly profile sin(pi t)^e (t from 0 to 1 along the
/// structure; e = `profile_proximal` for t < 1/2, else `profile_distal`: round ends with 0.5,
/// a full belly tapering into tendons with 0.6, a blunt end with 0.2). Azimuths are degrees
/// around the bone, 0 anterior, +90 lateral. The station planes are perpendicular to the bone,
/// or tilted by `tilt` degrees so that they rise (towards the bone's distal end) anteriorly,
/// e.g. the base of the brain, higher over the orbits than at the occiput.
struct GeneratedShape {
  std::string bone;
  SectionShape section = SectionShape::kEllipse;
  float from = 0, to = 1;
  float azimuth = 0;
  float profile_proximal = 0.6f;
  float profile_distal = 0.6f;
  float tilt = 0;  ///< degrees
  // kEllipse
  float depth = 0.5f;
  float thickness = 0.3f;
  float width = 1.0f;
  // kSector
  float span = 60.0f;  ///< degrees
  float inner = 0.3f;
  float outer = 0.85f;
  // kCavity
  float inset = 0.012f;     ///< m
  Side half = Side::kNone;  ///< kNone: the whole cavity
  float fissure = 0.004f;   ///< m
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
