#pragma once
// Analytic scene of the rig simulator: boxes, ellipsoids and vertical cylinders, ray cast
// exactly (no meshing), so rendered depth and the sampled true surface agree to float
// precision.

#include <optional>
#include <vector>

#include <Eigen/Geometry>

namespace vicc_tracking::sim {

enum class PrimitiveType { kBox, kEllipsoid, kCylinder };

struct Primitive {
  PrimitiveType type = PrimitiveType::kBox;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  /// Box: half extents; ellipsoid: radii; cylinder: (radius, radius, half height).
  Eigen::Vector3d half_size = Eigen::Vector3d::Constant(0.05);
  double yaw = 0.0;  ///< rotation about the map's z axis, radians
  double albedo = 1.0;  ///< Lambertian reflectivity for the simulated amplitude image, >= 0
};

struct SurfacePoint {
  Eigen::Vector3d position;
  Eigen::Vector3d normal;
};

/// A ray's first intersection: ray parameter, the primitive hit and its outward unit normal
/// there (map frame).
struct RayHit {
  double t = 0.0;
  size_t primitive = 0;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
};

class Scene {
 public:
  explicit Scene(std::vector<Primitive> primitives);

  /// Smallest ray parameter t > min_t where origin + t * direction hits the scene (the
  /// direction need not be unit length).
  std::optional<double> raycast(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                double min_t = 1e-6) const;
  /// As raycast, with the primitive hit and the surface normal at the hit.
  std::optional<RayHit> raycastHit(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                   double min_t = 1e-6) const;

  /// Points on the scene's outer surface, about `spacing` apart, with outward normals.
  /// Points inside another primitive (hidden faces) are left out.
  std::vector<SurfacePoint> sampleSurface(double spacing) const;

  const std::vector<Primitive>& primitives() const { return primitives_; }

 private:
  struct Prepared {
    Primitive primitive;
    Eigen::Matrix3d world_to_local;  ///< rotation by -yaw
    double bounding_radius;
  };
  bool inside(const Eigen::Vector3d& point, double margin) const;
  std::vector<Primitive> primitives_;
  std::vector<Prepared> prepared_;
};

}  // namespace vicc_tracking::sim
