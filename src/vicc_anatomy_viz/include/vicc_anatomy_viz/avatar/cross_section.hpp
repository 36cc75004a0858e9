#pragma once
// Cross-sections of a closed mesh by a plane: the closed contour loops where the plane cuts the
// skin (a horizontal slice through both thighs gives two loops). Landmarks and the radii of
// generated muscles are measured on them.

#include <Eigen/Core>

#include <optional>
#include <vector>

#include "vicc_anatomy_viz/avatar/avatar_model.hpp"

namespace vicc_anatomy_viz::avatar {

/// A plane with an in-plane orthonormal basis (u, v) for 2D contour coordinates.
struct SectionPlane {
  Eigen::Vector3f origin = Eigen::Vector3f::Zero();
  Eigen::Vector3f normal = Eigen::Vector3f::UnitZ();
  Eigen::Vector3f u = Eigen::Vector3f::UnitX();
  Eigen::Vector3f v = Eigen::Vector3f::UnitY();

  /// A plane through `origin` with `normal`; u is `preferred_u` made orthogonal (or any).
  static SectionPlane through(const Eigen::Vector3f& origin, const Eigen::Vector3f& normal,
                              const Eigen::Vector3f& preferred_u = Eigen::Vector3f::UnitX());
  Eigen::Vector2f project(const Eigen::Vector3f& point) const;
  Eigen::Vector3f lift(const Eigen::Vector2f& point) const;
};

/// One closed contour in plane coordinates.
struct SectionLoop {
  std::vector<Eigen::Vector2f> points;
  double area = 0;  ///< enclosed area, m^2 (always positive)
  Eigen::Vector2f centroid = Eigen::Vector2f::Zero();
  Eigen::Vector2f min_corner = Eigen::Vector2f::Zero();
  Eigen::Vector2f max_corner = Eigen::Vector2f::Zero();

  /// A loop through `points` (at least three, in order) with its area, centroid and bounds.
  static SectionLoop fromPoints(std::vector<Eigen::Vector2f> points);

  bool contains(const Eigen::Vector2f& point) const;
  /// Distance from `point` to the contour line.
  float distanceToContour(const Eigen::Vector2f& point) const;
  /// Nearest crossing of the ray from `origin` along `direction` with the contour, or nullopt.
  std::optional<float> rayDistance(const Eigen::Vector2f& origin,
                                   const Eigen::Vector2f& direction) const;
};

/// The contour loops of the mesh in the plane; loops with fewer than three points are dropped.
std::vector<SectionLoop> sliceMesh(const TriangleMesh& mesh, const SectionPlane& plane);

/// The loop that contains `point` (the smallest if nested), else nullptr.
const SectionLoop* loopContaining(const std::vector<SectionLoop>& loops,
                                  const Eigen::Vector2f& point);

}  // namespace vicc_anatomy_viz::avatar
