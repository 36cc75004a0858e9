#pragma once
// A tiny avatar for the view-logic tests: a skin of two triangles split into two dermatome
// regions, a right EHL mesh and two patellar tendons drawn only as proxies.

#include <string>

#include "vicc_anatomy_viz/avatar/avatar_model.hpp"
#include "vicc_anatomy_viz/status_encoder.hpp"

namespace vicc_anatomy_viz::avatar_view::testing {

inline avatar::TriangleMesh cube(const Eigen::Vector3f& centre, float half) {
  avatar::TriangleMesh mesh;
  for (int i = 0; i < 8; ++i)
    mesh.vertices.push_back(centre +
                            half * Eigen::Vector3f(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1));
  mesh.normals = mesh.vertices;
  mesh.triangles = {{0, 1, 2}, {1, 3, 2}, {4, 6, 5}, {5, 6, 7}};
  return mesh;
}

inline avatar::AvatarModel syntheticAvatar() {
  avatar::AvatarModel model;
  model.skin.vertices = {{0, -1, 0}, {0, 1, 0}, {0, 1, 2}, {0, -1, 2}};
  model.skin.normals.assign(4, Eigen::Vector3f::UnitX());
  model.skin.triangles = {{0, 1, 2}, {0, 2, 3}};
  model.skin_regions = {{"dermatome_L5", Side::kLeft, "Dermatome L5 (left)", {0}},
                        {"dermatome_L5", Side::kRight, "Dermatome L5 (right)", {1}}};
  avatar::AvatarStructure ehl;
  ehl.structure_id = "extensor_hallucis_longus";
  ehl.side = Side::kRight;
  ehl.structure_class = "muscle";
  ehl.mesh = cube({0.f, -0.1f, 0.2f}, 0.02f);
  model.structures.push_back(ehl);
  for (Side side : {Side::kLeft, Side::kRight}) {
    avatar::AvatarStructure tendon;
    tendon.structure_id = "patellar_tendon";
    tendon.side = side;
    tendon.structure_class = "tendon";
    tendon.has_proxy = true;
    tendon.proxy.radius = 0.03f;
    model.structures.push_back(tendon);
  }
  return model;
}

inline EncodedStructure entry(const std::string& id, Side side, const std::string& category,
                              Rgba color = {1.f, 0.f, 0.f, 1.f}) {
  EncodedStructure structure;
  structure.structure_id = id;
  structure.side = side;
  structure.category = category;
  structure.color = color;
  structure.display_name = id;
  return structure;
}

inline EncodedStatus statusWith(std::vector<EncodedStructure> structures) {
  EncodedStatus status;
  status.patient_id = "SDH-T";
  status.has_examination = true;
  status.structures = std::move(structures);
  return status;
}

}  // namespace vicc_anatomy_viz::avatar_view::testing
