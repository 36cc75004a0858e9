#include "vicc_anatomy_viz/avatar/cross_section.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <unordered_map>
#include <utility>

namespace vicc_anatomy_viz::avatar {

namespace {

std::uint64_t edgeKey(int a, int b) {
  const auto low = static_cast<std::uint64_t>(std::min(a, b));
  const auto high = static_cast<std::uint64_t>(std::max(a, b));
  return (high << 32) | low;
}

float cross2(const Eigen::Vector2f& a, const Eigen::Vector2f& b) {
  return a.x() * b.y() - a.y() * b.x();
}

void computeShape(SectionLoop& loop) {
  double twice_area = 0, cx = 0, cy = 0;
  loop.min_corner = loop.max_corner = loop.points.front();
  for (std::size_t i = 0; i < loop.points.size(); ++i) {
    const Eigen::Vector2f& a = loop.points[i];
    const Eigen::Vector2f& b = loop.points[(i + 1) % loop.points.size()];
    const double cross = static_cast<double>(cross2(a, b));
    twice_area += cross;
    cx += (a.x() + b.x()) * cross;
    cy += (a.y() + b.y()) * cross;
    loop.min_corner = loop.min_corner.cwiseMin(a);
    loop.max_corner = loop.max_corner.cwiseMax(a);
  }
  loop.area = std::abs(twice_area) / 2;
  if (std::abs(twice_area) > 1e-12) {
    loop.centroid = Eigen::Vector2f(static_cast<float>(cx / (3 * twice_area)),
                                    static_cast<float>(cy / (3 * twice_area)));
  } else {
    loop.centroid = (loop.min_corner + loop.max_corner) / 2;
  }
}

/// Where the plane crosses each edge of the triangle: the cut segment as two edge keys.
struct TriangleCut {
  std::uint64_t from_edge = 0;
  std::uint64_t to_edge = 0;
};

}  // namespace

SectionPlane SectionPlane::through(const Eigen::Vector3f& origin, const Eigen::Vector3f& normal,
                                   const Eigen::Vector3f& preferred_u) {
  SectionPlane plane;
  plane.origin = origin;
  plane.normal = normal.normalized();
  Eigen::Vector3f u = preferred_u - preferred_u.dot(plane.normal) * plane.normal;
  if (u.norm() < 1e-4f) u = plane.normal.unitOrthogonal();
  plane.u = u.normalized();
  plane.v = plane.normal.cross(plane.u);
  return plane;
}

Eigen::Vector2f SectionPlane::project(const Eigen::Vector3f& point) const {
  const Eigen::Vector3f offset = point - origin;
  return {offset.dot(u), offset.dot(v)};
}

Eigen::Vector3f SectionPlane::lift(const Eigen::Vector2f& point) const {
  return origin + point.x() * u + point.y() * v;
}

SectionLoop SectionLoop::fromPoints(std::vector<Eigen::Vector2f> points) {
  SectionLoop loop;
  loop.points = std::move(points);
  if (!loop.points.empty()) computeShape(loop);
  return loop;
}

bool SectionLoop::contains(const Eigen::Vector2f& point) const {
  if ((point.array() < min_corner.array()).any() || (point.array() > max_corner.array()).any()) {
    return false;
  }
  bool inside = false;
  for (std::size_t i = 0, j = points.size() - 1; i < points.size(); j = i++) {
    const Eigen::Vector2f& a = points[i];
    const Eigen::Vector2f& b = points[j];
    if ((a.y() > point.y()) != (b.y() > point.y()) &&
        point.x() < (b.x() - a.x()) * (point.y() - a.y()) / (b.y() - a.y()) + a.x()) {
      inside = !inside;
    }
  }
  return inside;
}

float SectionLoop::distanceToContour(const Eigen::Vector2f& point) const {
  float best = std::numeric_limits<float>::max();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2f& a = points[i];
    const Eigen::Vector2f ab = points[(i + 1) % points.size()] - a;
    const float length2 = ab.squaredNorm();
    const float t = length2 > 0 ? std::clamp((point - a).dot(ab) / length2, 0.0f, 1.0f) : 0.0f;
    best = std::min(best, (point - (a + t * ab)).norm());
  }
  return best;
}

std::optional<float> SectionLoop::rayDistance(const Eigen::Vector2f& origin,
                                              const Eigen::Vector2f& direction) const {
  const Eigen::Vector2f d = direction.normalized();
  std::optional<float> nearest;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2f& a = points[i];
    const Eigen::Vector2f edge = points[(i + 1) % points.size()] - a;
    const float denominator = cross2(d, edge);
    if (std::abs(denominator) < 1e-12f) continue;
    const Eigen::Vector2f offset = a - origin;
    const float t = cross2(offset, edge) / denominator;  // along the ray
    const float s = cross2(offset, d) / denominator;     // along the edge
    if (t > 0 && s >= 0 && s <= 1 && (!nearest || t < *nearest)) nearest = t;
  }
  return nearest;
}

std::vector<SectionLoop> sliceMesh(const TriangleMesh& mesh, const SectionPlane& plane) {
  std::vector<float> height(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    height[i] = (mesh.vertices[i] - plane.origin).dot(plane.normal);
    // A vertex exactly on the plane counts as above, so every cut crosses edges properly.
    if (height[i] == 0.0f) height[i] = 1e-9f;
  }
  std::unordered_map<std::uint64_t, Eigen::Vector2f> edge_points;
  std::unordered_map<std::uint64_t, std::vector<std::uint64_t>> links;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    std::uint64_t crossed[2];
    int count = 0;
    for (int k = 0; k < 3 && count < 2; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      if ((height[a] > 0) == (height[b] > 0)) continue;
      const std::uint64_t key = edgeKey(a, b);
      if (!edge_points.count(key)) {
        const float s = height[a] / (height[a] - height[b]);
        edge_points[key] =
            plane.project(mesh.vertices[a] + s * (mesh.vertices[b] - mesh.vertices[a]));
      }
      crossed[count++] = key;
    }
    if (count != 2) continue;
    links[crossed[0]].push_back(crossed[1]);
    links[crossed[1]].push_back(crossed[0]);
  }
  std::vector<SectionLoop> loops;
  std::unordered_map<std::uint64_t, bool> visited;
  for (const auto& [start, unused] : links) {
    if (visited.count(start)) continue;
    SectionLoop loop;
    std::uint64_t previous = std::numeric_limits<std::uint64_t>::max(), current = start;
    while (!visited.count(current)) {
      visited[current] = true;
      loop.points.push_back(edge_points[current]);
      const std::vector<std::uint64_t>& next = links[current];
      std::uint64_t following = next.front();
      if (following == previous && next.size() > 1) following = next[1];
      previous = current;
      current = following;
    }
    if (loop.points.size() < 3) continue;
    computeShape(loop);
    loops.push_back(std::move(loop));
  }
  return loops;
}

const SectionLoop* loopContaining(const std::vector<SectionLoop>& loops,
                                  const Eigen::Vector2f& point) {
  const SectionLoop* best = nullptr;
  for (const SectionLoop& loop : loops) {
    if (loop.contains(point) && (!best || loop.area < best->area)) best = &loop;
  }
  return best;
}

}  // namespace vicc_anatomy_viz::avatar
