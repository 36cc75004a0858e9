#pragma once
// The avatar's geometry: the skin mesh (REP-103: x forward, y left, z up, metres, feet at z = 0),
// its dermatome labelling, and the inner structures (muscles, tendons, organs) that findings
// name. ROS-, Qt- and OGRE-free: built by the anatomy core, drawn by the rviz plugins.

#include <Eigen/Core>

#include <string>
#include <vector>

#include "vicc_anatomy_viz/anatomy_catalog.hpp"

namespace vicc_anatomy_viz::avatar {

struct TriangleMesh {
  std::vector<Eigen::Vector3f> vertices;
  std::vector<Eigen::Vector3f> normals;    ///< per vertex, unit length, pointing outwards
  std::vector<Eigen::Vector3i> triangles;  ///< counter-clockwise seen from outside
};

/// A proxy drawn on the skin above a structure too small to colour directly (thesis 4.3.2.5):
/// a disc of `radius` centred on the skin point `centre`, facing `normal`.
struct SkinProxy {
  Eigen::Vector3f centre = Eigen::Vector3f::Zero();
  Eigen::Vector3f normal = Eigen::Vector3f::UnitX();
  float radius = 0.0f;
};

/// One structure instance: a catalogue structure on one side ("none" for midline ones).
struct AvatarStructure {
  std::string structure_id;  ///< catalogue id, as in EncodedStructure.structure_id
  Side side = Side::kNone;
  std::string structure_class;  ///< catalogue class: muscle, tendon, urethra, ...
  std::string display_name;     ///< e.g. "M. tibialis anterior (right)"
  std::string fma_id;           ///< "" when the catalogue has none
  /// body -> region -> system -> structure, e.g. {"body", "lower limb", "muscular system",
  /// "M. tibialis anterior"}.
  std::vector<std::string> hierarchy;
  TriangleMesh mesh;  ///< empty for a structure drawn only as a proxy
  bool has_proxy = false;
  SkinProxy proxy;
};

/// A labelled region of the skin (a dermatome on one side): the skin triangles it covers.
struct SkinRegion {
  std::string structure_id;  ///< e.g. dermatome_L5
  Side side = Side::kNone;
  std::string display_name;
  std::vector<int> triangles;  ///< indices into AvatarModel::skin.triangles
};

struct AvatarModel {
  TriangleMesh skin;
  std::vector<SkinRegion> skin_regions;  ///< dermatomes; together they cover the skin
  std::vector<AvatarStructure> structures;

  /// The structure instance or skin region findings call (id, side); nullptr if the model
  /// has none.
  const AvatarStructure* structure(const std::string& id, Side side) const;
  const SkinRegion* skinRegion(const std::string& id, Side side) const;
};

/// Builds the avatar a manifest describes (YAML: the skin mesh file, generated or atlas
/// structures with FMA ids and sides, the dermatome labelling), every structure named by the
/// manifest checked against the catalogue. Throws ConfigError naming the file and the problem
/// (missing mesh file, unknown structure, ...).
AvatarModel buildAvatarModel(const std::string& manifest_path, const AnatomyCatalog& catalog);

/// The package's default manifest (config/anatomy/avatar.yaml: the MakeHuman body of Debian's
/// assimp-testmodels, structures generated from its landmarks).
std::string defaultAvatarManifestPath();

}  // namespace vicc_anatomy_viz::avatar
