#include "vicc_anatomy_viz/avatar/avatar_model.hpp"

#include <chrono>
#include <filesystem>

#include "vicc_anatomy_viz/avatar/avatar_builder.hpp"
#include "vicc_anatomy_viz/avatar/dermatome_labelling.hpp"
#include "vicc_anatomy_viz/avatar/mesh_geometry.hpp"
#include "vicc_anatomy_viz/avatar/skin_mesh_loader.hpp"
#include "vicc_anatomy_viz/avatar/structure_generator.hpp"
#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/patient_status_service.hpp"

namespace vicc_anatomy_viz::avatar {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

AvatarStructure makeStructure(const AvatarBuild& build, const StructureEntry& entry, Side side,
                              const AnatomyCatalog& catalog) {
  const Structure& catalogued = *catalog.structure(entry.id);
  AvatarStructure structure;
  structure.structure_id = entry.id;
  structure.side = side;
  structure.structure_class = catalogued.class_id;
  structure.display_name = catalog.displayName(catalogued, side);
  structure.fma_id = entry.fma_id;
  structure.hierarchy = {"body", entry.region, entry.system, catalogued.name};
  const std::string what =
      build.manifest.path + ": " + entry.where + " (" + entry.id + ", " + toString(side) + ")";
  const TriangleMesh& skin = build.model.skin;
  if (!entry.generated.empty()) {
    for (const GeneratedShape& part : entry.generated)
      appendMeshPart(structure.mesh,
                     generateShape(skin, build.landmarks, part, side, kStructureSkinMargin, what));
  } else if (entry.mesh) {
    structure.mesh = loadAtlasMesh(*entry.mesh);
  }
  if (entry.proxy) {
    structure.has_proxy = true;
    structure.proxy = placeProxy(skin, build.landmarks, *entry.proxy, side, what);
  }
  return structure;
}

}  // namespace

const AvatarStructure* AvatarModel::structure(const std::string& id, Side side) const {
  for (const AvatarStructure& candidate : structures) {
    if (candidate.structure_id == id && candidate.side == side) return &candidate;
  }
  return nullptr;
}

const SkinRegion* AvatarModel::skinRegion(const std::string& id, Side side) const {
  for (const SkinRegion& candidate : skin_regions) {
    if (candidate.structure_id == id && candidate.side == side) return &candidate;
  }
  return nullptr;
}

AvatarBuild buildAvatar(const std::string& manifest_path, const AnatomyCatalog& catalog) {
  const Clock::time_point start = Clock::now();
  AvatarBuild build;
  build.manifest = loadAvatarManifest(manifest_path, catalog);
  build.model.skin = loadSkinMesh(build.manifest.skin);
  build.times.load_seconds = secondsSince(start);
  Clock::time_point step = Clock::now();
  build.landmarks = estimateLandmarks(build.model.skin);
  build.times.landmark_seconds = secondsSince(step);
  step = Clock::now();
  for (const StructureEntry& entry : build.manifest.structures) {
    for (Side side : entry.sides) {
      build.model.structures.push_back(makeStructure(build, entry, side, catalog));
    }
  }
  build.times.structure_seconds = secondsSince(step);
  step = Clock::now();
  build.model.skin_regions = labelDermatomes(build.model.skin, build.landmarks, catalog);
  build.times.dermatome_seconds = secondsSince(step);
  build.times.total_seconds = secondsSince(start);
  return build;
}

AvatarModel buildAvatarModel(const std::string& manifest_path, const AnatomyCatalog& catalog) {
  return buildAvatar(manifest_path, catalog).model;
}

std::string defaultAvatarManifestPath() {
  // Next to the anatomy catalogue, found the same way (share/ of the devel or install space).
  return (std::filesystem::path(defaultAnatomyConfigPath()).parent_path() / "avatar.yaml").string();
}

}  // namespace vicc_anatomy_viz::avatar
