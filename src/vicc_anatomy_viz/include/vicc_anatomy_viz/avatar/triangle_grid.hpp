#pragma once
// A uniform grid over a mesh's triangles for fast ray casts and nearest-triangle queries (the
// dermatome seeds need thousands of both on the skin).

#include <Eigen/Core>

#include <optional>
#include <vector>

#include "vicc_anatomy_viz/avatar/avatar_model.hpp"

namespace vicc_anatomy_viz::avatar {

class TriangleGrid {
 public:
  /// Keeps a reference to `mesh`, which must outlive the grid. `cell_size` in metres.
  explicit TriangleGrid(const TriangleMesh& mesh, float cell_size = 0.03f);

  /// First hit of origin + t * direction (t > 0) with the mesh, as castRay.
  std::optional<Eigen::Vector3f> castRay(const Eigen::Vector3f& origin,
                                         const Eigen::Vector3f& direction) const;
  /// The triangle whose centroid is nearest to `point`.
  int nearestTriangle(const Eigen::Vector3f& point) const;
  const Eigen::Vector3f& centroid(int triangle) const { return centroids_[triangle]; }

 private:
  Eigen::Vector3i cellOf(const Eigen::Vector3f& point) const;
  bool inside(const Eigen::Vector3i& cell) const;
  const std::vector<int>& cell(const Eigen::Vector3i& index) const;
  /// Nearest hit distance along the unit ray with the triangles of one cell.
  void hitCell(const Eigen::Vector3i& index, const Eigen::Vector3f& origin,
               const Eigen::Vector3f& direction, float& nearest) const;

  const TriangleMesh& mesh_;
  float cell_size_;
  Eigen::Vector3f lower_;
  Eigen::Vector3i dimensions_;
  std::vector<std::vector<int>> cells_;  ///< triangles overlapping each cell (by bounding box)
  std::vector<std::vector<int>> centroid_cells_;  ///< triangles whose centroid is in each cell
  std::vector<Eigen::Vector3f> centroids_;
};

}  // namespace vicc_anatomy_viz::avatar
