#include "vicc_anatomy_viz/avatar/mesh_geometry.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <unordered_map>

namespace vicc_anatomy_viz::avatar {

namespace {

std::uint64_t edgeKey(int a, int b) {
  const auto low = static_cast<std::uint64_t>(std::min(a, b));
  const auto high = static_cast<std::uint64_t>(std::max(a, b));
  return (high << 32) | low;
}

/// Squared distance from p to the triangle abc (Ericson, Real-Time Collision Detection 5.1.5).
float squaredDistanceToTriangle(const Eigen::Vector3f& p, const Eigen::Vector3f& a,
                                const Eigen::Vector3f& b, const Eigen::Vector3f& c) {
  const Eigen::Vector3f ab = b - a, ac = c - a, ap = p - a;
  const float d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.squaredNorm();
  const Eigen::Vector3f bp = p - b;
  const float d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.squaredNorm();
  const float vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + ab * (d1 / (d1 - d3)))).squaredNorm();
  const Eigen::Vector3f cp = p - c;
  const float d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.squaredNorm();
  const float vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + ac * (d2 / (d2 - d6)))).squaredNorm();
  const float va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return (p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))))).squaredNorm();
  }
  const float denominator = 1.0f / (va + vb + vc);
  return (p - (a + ab * (vb * denominator) + ac * (vc * denominator))).squaredNorm();
}

}  // namespace

std::vector<Eigen::Vector3f> vertexNormals(const TriangleMesh& mesh) {
  std::vector<Eigen::Vector3f> normals(mesh.vertices.size(), Eigen::Vector3f::Zero());
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Eigen::Vector3f& a = mesh.vertices[t[0]];
    // The cross product's length is twice the area: larger triangles weigh more.
    const Eigen::Vector3f weighted = (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a);
    for (int k = 0; k < 3; ++k) normals[t[k]] += weighted;
  }
  for (Eigen::Vector3f& normal : normals) {
    const float length = normal.norm();
    normal = length > 0 ? Eigen::Vector3f(normal / length) : Eigen::Vector3f::UnitZ();
  }
  return normals;
}

void appendMeshPart(TriangleMesh& mesh, const TriangleMesh& part) {
  const int offset = static_cast<int>(mesh.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), part.vertices.begin(), part.vertices.end());
  mesh.normals.insert(mesh.normals.end(), part.normals.begin(), part.normals.end());
  for (const Eigen::Vector3i& triangle : part.triangles)
    mesh.triangles.push_back(triangle + Eigen::Vector3i::Constant(offset));
}

double signedVolume(const TriangleMesh& mesh) {
  double volume = 0;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Eigen::Vector3d a = mesh.vertices[t[0]].cast<double>();
    const Eigen::Vector3d b = mesh.vertices[t[1]].cast<double>();
    const Eigen::Vector3d c = mesh.vertices[t[2]].cast<double>();
    volume += a.dot(b.cross(c));
  }
  return volume / 6.0;
}

void orientOutwards(TriangleMesh& mesh) {
  if (signedVolume(mesh) >= 0) return;
  for (Eigen::Vector3i& t : mesh.triangles) std::swap(t[1], t[2]);
  for (Eigen::Vector3f& normal : mesh.normals) normal = -normal;
}

double windingNumber(const TriangleMesh& mesh, const Eigen::Vector3f& point) {
  // Sum of the solid angles of the triangles seen from the point (Van Oosterom & Strackee).
  double solid_angle = 0;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Eigen::Vector3d a = (mesh.vertices[t[0]] - point).cast<double>();
    const Eigen::Vector3d b = (mesh.vertices[t[1]] - point).cast<double>();
    const Eigen::Vector3d c = (mesh.vertices[t[2]] - point).cast<double>();
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    solid_angle += 2.0 * std::atan2(numerator, denominator);
  }
  return solid_angle / (4.0 * M_PI);
}

float distanceToSurface(const TriangleMesh& mesh, const Eigen::Vector3f& point) {
  float best = std::numeric_limits<float>::max();
  for (const Eigen::Vector3i& t : mesh.triangles) {
    best = std::min(best, squaredDistanceToTriangle(point, mesh.vertices[t[0]], mesh.vertices[t[1]],
                                                    mesh.vertices[t[2]]));
  }
  return std::sqrt(best);
}

std::optional<Eigen::Vector3f> castRay(const TriangleMesh& mesh, const Eigen::Vector3f& origin,
                                       const Eigen::Vector3f& direction) {
  // Moeller-Trumbore against every triangle: the model is built once, a few dozen rays.
  const Eigen::Vector3f d = direction.normalized();
  float nearest = std::numeric_limits<float>::max();
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Eigen::Vector3f& a = mesh.vertices[t[0]];
    const Eigen::Vector3f e1 = mesh.vertices[t[1]] - a, e2 = mesh.vertices[t[2]] - a;
    const Eigen::Vector3f p = d.cross(e2);
    const float determinant = e1.dot(p);
    if (std::abs(determinant) < 1e-12f) continue;
    const Eigen::Vector3f s = origin - a;
    const float u = s.dot(p) / determinant;
    if (u < 0 || u > 1) continue;
    const Eigen::Vector3f q = s.cross(e1);
    const float v = d.dot(q) / determinant;
    if (v < 0 || u + v > 1) continue;
    const float distance = e2.dot(q) / determinant;
    if (distance > 1e-6f && distance < nearest) nearest = distance;
  }
  if (nearest == std::numeric_limits<float>::max()) return std::nullopt;
  return Eigen::Vector3f(origin + nearest * d);
}

VertexGraph vertexGraph(const TriangleMesh& mesh) {
  VertexGraph graph(mesh.vertices.size());
  std::unordered_map<std::uint64_t, bool> seen;
  seen.reserve(mesh.triangles.size() * 2);
  for (const Eigen::Vector3i& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      if (!seen.emplace(edgeKey(a, b), true).second) continue;
      const float length = (mesh.vertices[a] - mesh.vertices[b]).norm();
      graph[a].emplace_back(b, length);
      graph[b].emplace_back(a, length);
    }
  }
  return graph;
}

int nearestVertex(const TriangleMesh& mesh, const Eigen::Vector3f& point) {
  int best = -1;
  float best_distance = std::numeric_limits<float>::max();
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const float distance = (mesh.vertices[i] - point).squaredNorm();
    if (distance < best_distance) {
      best_distance = distance;
      best = static_cast<int>(i);
    }
  }
  return best;
}

std::vector<std::vector<int>> triangleNeighbours(const TriangleMesh& mesh) {
  std::unordered_map<std::uint64_t, int> first_triangle;
  first_triangle.reserve(mesh.triangles.size() * 2);
  std::vector<std::vector<int>> neighbours(mesh.triangles.size());
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const Eigen::Vector3i& t = mesh.triangles[i];
    for (int k = 0; k < 3; ++k) {
      const auto [entry, inserted] =
          first_triangle.emplace(edgeKey(t[k], t[(k + 1) % 3]), static_cast<int>(i));
      if (inserted) continue;
      neighbours[i].push_back(entry->second);
      neighbours[entry->second].push_back(static_cast<int>(i));
    }
  }
  return neighbours;
}

}  // namespace vicc_anatomy_viz::avatar
