#include "vicc_anatomy_viz/rviz/avatar_meshes.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <cstdint>
#include <vector>

#include "vicc_anatomy_viz/avatar_view/procedural_texture.hpp"

namespace vicc_anatomy_viz::rviz_plugin {
namespace {

Ogre::Vector3 ogre(const Eigen::Vector3f& v) { return {v.x(), v.y(), v.z()}; }

void addVertex(Ogre::ManualObject& object, const Eigen::Vector3f& position,
               const Eigen::Vector3f& normal, float texture_frequency) {
  object.position(ogre(position));
  object.normal(ogre(normal));
  const Eigen::Vector2f uv =
      avatar_view::textureCoordinate(position, normal, std::max(texture_frequency, 1.f));
  object.textureCoord(uv.x(), uv.y());
}

bool validTriangle(const avatar::TriangleMesh& mesh, const Eigen::Vector3i& triangle) {
  const int count = static_cast<int>(mesh.vertices.size());
  return (triangle.array() >= 0).all() && (triangle.array() < count).all();
}

}  // namespace

void addMeshSection(Ogre::ManualObject& object, const avatar::TriangleMesh& mesh,
                    const std::vector<int>* triangles, const std::string& material, float lift,
                    float texture_frequency) {
  const bool has_normals = mesh.normals.size() == mesh.vertices.size();
  const std::size_t count = triangles ? triangles->size() : mesh.triangles.size();
  object.begin(material, Ogre::RenderOperation::OT_TRIANGLE_LIST);
  // With vertex normals every mesh vertex is emitted once and shared by its triangles (the
  // vertex stage, fixed-function lighting included, runs once per vertex, not per corner);
  // with face normals each corner is its own vertex.
  std::vector<std::int64_t> emitted_index(has_normals ? mesh.vertices.size() : 0, -1);
  std::uint32_t emitted = 0;
  const auto corner = [&](int vertex, const Eigen::Vector3f& face) -> std::uint32_t {
    if (has_normals && emitted_index[vertex] >= 0)
      return static_cast<std::uint32_t>(emitted_index[vertex]);
    const Eigen::Vector3f normal = has_normals ? mesh.normals[vertex] : face;
    addVertex(object, mesh.vertices[vertex] + lift * normal, normal, texture_frequency);
    if (has_normals) emitted_index[vertex] = emitted;
    return emitted++;
  };
  for (std::size_t t = 0; t < count; ++t) {
    const int index = triangles ? (*triangles)[t] : static_cast<int>(t);
    if (index < 0 || index >= static_cast<int>(mesh.triangles.size())) continue;
    const Eigen::Vector3i& triangle = mesh.triangles[static_cast<std::size_t>(index)];
    if (!validTriangle(mesh, triangle)) continue;
    const Eigen::Vector3f face = (mesh.vertices[triangle[1]] - mesh.vertices[triangle[0]])
                                     .cross(mesh.vertices[triangle[2]] - mesh.vertices[triangle[0]])
                                     .normalized();
    const std::uint32_t a = corner(triangle[0], face), b = corner(triangle[1], face),
                        c = corner(triangle[2], face);
    object.triangle(a, b, c);
  }
  object.end();
}

void addProxyDisc(Ogre::ManualObject& object, const avatar::SkinProxy& proxy,
                  const std::string& material, float lift, float texture_frequency) {
  constexpr int kSegments = 32;
  const Eigen::Vector3f normal = proxy.normal.normalized();
  const Eigen::Vector3f u = normal.unitOrthogonal();
  const Eigen::Vector3f v = normal.cross(u);
  const Eigen::Vector3f centre = proxy.centre + lift * normal;
  object.begin(material, Ogre::RenderOperation::OT_TRIANGLE_LIST);
  addVertex(object, centre, normal, texture_frequency);
  for (int i = 0; i <= kSegments; ++i) {
    const float angle = 2.f * static_cast<float>(M_PI) * static_cast<float>(i) / kSegments;
    const Eigen::Vector3f rim = centre + proxy.radius * (std::cos(angle) * u + std::sin(angle) * v);
    addVertex(object, rim, normal, texture_frequency);
    if (i > 0) object.triangle(0, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(i + 1));
  }
  object.end();
}

bool meshBounds(const avatar::TriangleMesh& mesh, Eigen::Vector3f& min, Eigen::Vector3f& max) {
  if (mesh.vertices.empty()) return false;
  min = max = mesh.vertices.front();
  for (const Eigen::Vector3f& vertex : mesh.vertices) {
    min = min.cwiseMin(vertex);
    max = max.cwiseMax(vertex);
  }
  return true;
}

}  // namespace vicc_anatomy_viz::rviz_plugin
