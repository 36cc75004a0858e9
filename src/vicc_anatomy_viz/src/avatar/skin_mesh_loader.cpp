#include "vicc_anatomy_viz/avatar/skin_mesh_loader.hpp"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <Eigen/Geometry>
#include <assimp/Importer.hpp>

#include <filesystem>
#include <map>
#include <unordered_map>

#include "vicc_anatomy_viz/avatar/mesh_geometry.hpp"
#include "vicc_anatomy_viz/errors.hpp"

namespace vicc_anatomy_viz::avatar {

namespace {

[[noreturn]] void fail(const MeshSource& source, const std::string& problem) {
  throw ConfigError("mesh file '" + source.path + "': " + problem);
}

Eigen::Vector3f signedAxis(const MeshSource& source, const std::string& text,
                           const std::string& key) {
  static const std::map<std::string, Eigen::Vector3f> axes = {
      {"+x", Eigen::Vector3f::UnitX()}, {"-x", -Eigen::Vector3f::UnitX()},
      {"+y", Eigen::Vector3f::UnitY()}, {"-y", -Eigen::Vector3f::UnitY()},
      {"+z", Eigen::Vector3f::UnitZ()}, {"-z", -Eigen::Vector3f::UnitZ()}};
  const auto found = axes.find(text);
  if (found == axes.end())
    fail(source, key + " must be one of +x -x +y -y +z -z, not '" + text + "'");
  return found->second;
}

/// Rows: the file's forward, left and up directions, so that R * p is in REP-103. Left is
/// up x forward, which keeps the rotation proper (a mirrored body would swap its sides).
Eigen::Matrix3f rep103Rotation(const MeshSource& source) {
  const Eigen::Vector3f up = signedAxis(source, source.up_axis, "up_axis");
  const Eigen::Vector3f forward = signedAxis(source, source.forward_axis, "forward_axis");
  if (std::abs(up.dot(forward)) > 0.5f) fail(source, "up_axis and forward_axis are parallel");
  Eigen::Matrix3f rotation;
  rotation.row(0) = forward;
  rotation.row(1) = up.cross(forward);
  rotation.row(2) = up;
  return rotation;
}

/// Appends the mesh's triangles, welding vertices that share a position (seams of the
/// texture or the normals split them in the file).
void appendMesh(const aiMesh& source_mesh, const Eigen::Matrix3f& rotation, float scale,
                std::map<std::tuple<long, long, long>, int>& welded, TriangleMesh& mesh) {
  std::vector<int> index(source_mesh.mNumVertices);
  for (unsigned i = 0; i < source_mesh.mNumVertices; ++i) {
    const aiVector3D& p = source_mesh.mVertices[i];
    const Eigen::Vector3f point = rotation * Eigen::Vector3f(p.x, p.y, p.z) * scale;
    // Positions within 1e-5 m are one vertex.
    const auto key = std::make_tuple(std::lround(point.x() * 1e5f), std::lround(point.y() * 1e5f),
                                     std::lround(point.z() * 1e5f));
    const auto [entry, inserted] = welded.emplace(key, static_cast<int>(mesh.vertices.size()));
    if (inserted) mesh.vertices.push_back(point);
    index[i] = entry->second;
  }
  for (unsigned f = 0; f < source_mesh.mNumFaces; ++f) {
    const aiFace& face = source_mesh.mFaces[f];
    if (face.mNumIndices != 3) continue;  // points and lines left by triangulation
    const Eigen::Vector3i triangle(index[face.mIndices[0]], index[face.mIndices[1]],
                                   index[face.mIndices[2]]);
    if (triangle[0] == triangle[1] || triangle[1] == triangle[2] || triangle[0] == triangle[2]) {
      continue;  // collapsed by the weld
    }
    mesh.triangles.push_back(triangle);
  }
}

/// Every edge must join exactly two triangles: inside tests and geodesics need a closed skin.
void requireClosed(const MeshSource& source, const TriangleMesh& mesh) {
  std::unordered_map<std::uint64_t, int> uses;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const auto a = static_cast<std::uint64_t>(std::min(t[k], t[(k + 1) % 3]));
      const auto b = static_cast<std::uint64_t>(std::max(t[k], t[(k + 1) % 3]));
      ++uses[(b << 32) | a];
    }
  }
  std::size_t open = 0;
  for (const auto& [edge, count] : uses) open += count != 2;
  if (open > 0)
    fail(source, std::to_string(open) +
                     " edges are not shared by exactly two triangles "
                     "(the skin must be a closed surface)");
}

/// Feet on z = 0, the centre of volume above the origin.
void placeOnFloor(TriangleMesh& mesh) {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double volume = 0;
  float floor = std::numeric_limits<float>::max();
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Eigen::Vector3d a = mesh.vertices[t[0]].cast<double>();
    const Eigen::Vector3d b = mesh.vertices[t[1]].cast<double>();
    const Eigen::Vector3d c = mesh.vertices[t[2]].cast<double>();
    const double tetrahedron = a.dot(b.cross(c)) / 6.0;
    volume += tetrahedron;
    centre += tetrahedron * (a + b + c) / 4.0;
  }
  for (const Eigen::Vector3f& v : mesh.vertices) floor = std::min(floor, v.z());
  centre /= volume;
  const Eigen::Vector3f shift(-static_cast<float>(centre.x()), -static_cast<float>(centre.y()),
                              -floor);
  for (Eigen::Vector3f& v : mesh.vertices) v += shift;
}

/// The file's triangles in REP-103 axes and metres, duplicate vertices merged.
TriangleMesh readMeshFile(const MeshSource& source) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(source.path, error)) fail(source, "no such file");
  if (!(source.unit_in_metres > 0)) fail(source, "unit_in_metres must be positive");
  const Eigen::Matrix3f rotation = rep103Rotation(source);
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(
      source.path, aiProcess_Triangulate | aiProcess_PreTransformVertices | aiProcess_SortByPType);
  if (!scene || !scene->HasMeshes()) {
    fail(source, std::string("unreadable: ") + importer.GetErrorString());
  }
  TriangleMesh mesh;
  std::map<std::tuple<long, long, long>, int> welded;
  bool found = false;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh& candidate = *scene->mMeshes[m];
    if (!source.mesh_name.empty() && source.mesh_name != candidate.mName.C_Str()) continue;
    found = true;
    appendMesh(candidate, rotation, source.unit_in_metres, welded, mesh);
  }
  if (!found) fail(source, "has no mesh named '" + source.mesh_name + "'");
  if (mesh.triangles.empty()) fail(source, "has no triangles");
  return mesh;
}

}  // namespace

TriangleMesh loadSkinMesh(const MeshSource& source) {
  TriangleMesh mesh = readMeshFile(source);
  requireClosed(source, mesh);
  if (std::abs(signedVolume(mesh)) < 1e-6) fail(source, "encloses no volume");
  orientOutwards(mesh);
  placeOnFloor(mesh);
  mesh.normals = vertexNormals(mesh);
  return mesh;
}

TriangleMesh loadAtlasMesh(const MeshSource& source) {
  TriangleMesh mesh = readMeshFile(source);
  const Eigen::Vector3f shift(source.translation[0], source.translation[1], source.translation[2]);
  for (Eigen::Vector3f& vertex : mesh.vertices) vertex += shift;
  orientOutwards(mesh);
  mesh.normals = vertexNormals(mesh);
  return mesh;
}

}  // namespace vicc_anatomy_viz::avatar
