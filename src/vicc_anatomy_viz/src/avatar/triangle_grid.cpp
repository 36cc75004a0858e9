#include "vicc_anatomy_viz/avatar/triangle_grid.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <limits>

#include "vicc_anatomy_viz/avatar/mesh_geometry.hpp"

namespace vicc_anatomy_viz::avatar {

namespace {

constexpr float kNone = std::numeric_limits<float>::max();

/// Moeller-Trumbore: distance along the unit ray, or kNone.
float rayTriangle(const Eigen::Vector3f& origin, const Eigen::Vector3f& d, const Eigen::Vector3f& a,
                  const Eigen::Vector3f& b, const Eigen::Vector3f& c) {
  const Eigen::Vector3f e1 = b - a, e2 = c - a;
  const Eigen::Vector3f p = d.cross(e2);
  const float determinant = e1.dot(p);
  if (std::abs(determinant) < 1e-12f) return kNone;
  const Eigen::Vector3f s = origin - a;
  const float u = s.dot(p) / determinant;
  if (u < 0 || u > 1) return kNone;
  const Eigen::Vector3f q = s.cross(e1);
  const float v = d.dot(q) / determinant;
  if (v < 0 || u + v > 1) return kNone;
  const float distance = e2.dot(q) / determinant;
  return distance > 1e-6f ? distance : kNone;
}

}  // namespace

TriangleGrid::TriangleGrid(const TriangleMesh& mesh, float cell_size)
    : mesh_(mesh), cell_size_(cell_size) {
  Eigen::Vector3f lower = Eigen::Vector3f::Constant(kNone), upper = -lower;
  for (const Eigen::Vector3f& v : mesh.vertices) {
    lower = lower.cwiseMin(v);
    upper = upper.cwiseMax(v);
  }
  lower_ = lower - Eigen::Vector3f::Constant(cell_size);
  for (int k = 0; k < 3; ++k) {
    dimensions_[k] = static_cast<int>(std::ceil((upper[k] - lower_[k]) / cell_size)) + 2;
  }
  const std::size_t count = static_cast<std::size_t>(dimensions_.prod());
  cells_.resize(count);
  centroid_cells_.resize(count);
  const auto flat = [this](const Eigen::Vector3i& c) {
    return static_cast<std::size_t>((c.z() * dimensions_.y() + c.y()) * dimensions_.x() + c.x());
  };
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Eigen::Vector3i& triangle = mesh.triangles[t];
    const Eigen::Vector3f& a = mesh.vertices[triangle[0]];
    const Eigen::Vector3f& b = mesh.vertices[triangle[1]];
    const Eigen::Vector3f& c = mesh.vertices[triangle[2]];
    centroids_.push_back((a + b + c) / 3);
    centroid_cells_[flat(cellOf(centroids_.back()))].push_back(static_cast<int>(t));
    const Eigen::Vector3i from = cellOf(a.cwiseMin(b).cwiseMin(c));
    const Eigen::Vector3i to = cellOf(a.cwiseMax(b).cwiseMax(c));
    for (int z = from.z(); z <= to.z(); ++z) {
      for (int y = from.y(); y <= to.y(); ++y) {
        for (int x = from.x(); x <= to.x(); ++x)
          cells_[flat({x, y, z})].push_back(static_cast<int>(t));
      }
    }
  }
}

Eigen::Vector3i TriangleGrid::cellOf(const Eigen::Vector3f& point) const {
  Eigen::Vector3i index;
  for (int k = 0; k < 3; ++k) {
    index[k] = std::clamp(static_cast<int>(std::floor((point[k] - lower_[k]) / cell_size_)), 0,
                          dimensions_[k] - 1);
  }
  return index;
}

bool TriangleGrid::inside(const Eigen::Vector3i& cell) const {
  return (cell.array() >= 0).all() && (cell.array() < dimensions_.array()).all();
}

const std::vector<int>& TriangleGrid::cell(const Eigen::Vector3i& c) const {
  return cells_[static_cast<std::size_t>((c.z() * dimensions_.y() + c.y()) * dimensions_.x() +
                                         c.x())];
}

void TriangleGrid::hitCell(const Eigen::Vector3i& index, const Eigen::Vector3f& origin,
                           const Eigen::Vector3f& direction, float& nearest) const {
  for (int t : cell(index)) {
    const Eigen::Vector3i& triangle = mesh_.triangles[t];
    nearest =
        std::min(nearest, rayTriangle(origin, direction, mesh_.vertices[triangle[0]],
                                      mesh_.vertices[triangle[1]], mesh_.vertices[triangle[2]]));
  }
}

std::optional<Eigen::Vector3f> TriangleGrid::castRay(const Eigen::Vector3f& origin,
                                                     const Eigen::Vector3f& direction) const {
  // Amanatides & Woo's grid walk from the origin's cell; from outside the grid, every triangle.
  const Eigen::Vector3f upper = lower_ + cell_size_ * dimensions_.cast<float>();
  if ((origin.array() < lower_.array()).any() || (origin.array() >= upper.array()).any()) {
    return avatar::castRay(mesh_, origin, direction);
  }
  const Eigen::Vector3f d = direction.normalized();
  Eigen::Vector3i index = cellOf(origin);
  Eigen::Vector3i step;
  Eigen::Vector3f next_boundary, delta;
  for (int k = 0; k < 3; ++k) {
    step[k] = d[k] > 0 ? 1 : -1;
    const float boundary = lower_[k] + (index[k] + (d[k] > 0 ? 1 : 0)) * cell_size_;
    next_boundary[k] = std::abs(d[k]) > 1e-9f ? (boundary - origin[k]) / d[k] : kNone;
    delta[k] = std::abs(d[k]) > 1e-9f ? cell_size_ / std::abs(d[k]) : kNone;
  }
  float nearest = kNone;
  while (inside(index)) {
    hitCell(index, origin, d, nearest);
    int axis = 0;
    if (next_boundary[1] < next_boundary[axis]) axis = 1;
    if (next_boundary[2] < next_boundary[axis]) axis = 2;
    // A hit before the exit of this cell cannot be beaten by later cells.
    if (nearest <= next_boundary[axis]) break;
    index[axis] += step[axis];
    next_boundary[axis] += delta[axis];
  }
  if (nearest == kNone) return std::nullopt;
  return Eigen::Vector3f(origin + nearest * d);
}

int TriangleGrid::nearestTriangle(const Eigen::Vector3f& point) const {
  const Eigen::Vector3i centre = cellOf(point);
  int best = -1;
  float best_distance = kNone;
  const int max_ring = dimensions_.maxCoeff();
  for (int ring = 0; ring <= max_ring; ++ring) {
    // Every centroid beyond this shell is at least (ring - 1) cells away.
    if (best >= 0 && (ring - 1) * cell_size_ > std::sqrt(best_distance)) break;
    for (int z = centre.z() - ring; z <= centre.z() + ring; ++z) {
      for (int y = centre.y() - ring; y <= centre.y() + ring; ++y) {
        for (int x = centre.x() - ring; x <= centre.x() + ring; ++x) {
          const Eigen::Vector3i index(x, y, z);
          if ((index - centre).cwiseAbs().maxCoeff() != ring || !inside(index)) continue;
          for (int t : centroid_cells_[static_cast<std::size_t>(
                   (z * dimensions_.y() + y) * dimensions_.x() + x)]) {
            const float distance = (centroids_[t] - point).squaredNorm();
            if (distance < best_distance) {
              best_distance = distance;
              best = t;
            }
          }
        }
      }
    }
  }
  return best;
}

}  // namespace vicc_anatomy_viz::avatar
