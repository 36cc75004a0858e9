#include "vicc_tracking/sim/scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vicc_tracking::sim {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Slab test against the axis-aligned box [-h, h] in local coordinates.
std::optional<double> hitBox(const Eigen::Vector3d& o, const Eigen::Vector3d& d,
                             const Eigen::Vector3d& h, double min_t) {
  double near = -kInfinity, far = kInfinity;
  for (int axis = 0; axis < 3; ++axis) {
    if (std::abs(d[axis]) < 1e-15) {
      if (std::abs(o[axis]) > h[axis]) return std::nullopt;
      continue;
    }
    double t0 = (-h[axis] - o[axis]) / d[axis];
    double t1 = (h[axis] - o[axis]) / d[axis];
    if (t0 > t1) std::swap(t0, t1);
    near = std::max(near, t0);
    far = std::min(far, t1);
  }
  if (near > far) return std::nullopt;
  if (near > min_t) return near;
  if (far > min_t) return far;
  return std::nullopt;
}

/// Smallest root > min_t of a t^2 + b t + c.
std::optional<double> smallestRoot(double a, double b, double c, double min_t) {
  const double discriminant = b * b - 4.0 * a * c;
  if (discriminant < 0.0 || a == 0.0) return std::nullopt;
  const double root = std::sqrt(discriminant);
  const double t0 = (-b - root) / (2.0 * a);
  const double t1 = (-b + root) / (2.0 * a);
  if (t0 > min_t) return t0;
  if (t1 > min_t) return t1;
  return std::nullopt;
}

std::optional<double> hitEllipsoid(const Eigen::Vector3d& o, const Eigen::Vector3d& d,
                                   const Eigen::Vector3d& radii, double min_t) {
  const Eigen::Vector3d os = o.cwiseQuotient(radii);
  const Eigen::Vector3d ds = d.cwiseQuotient(radii);
  return smallestRoot(ds.squaredNorm(), 2.0 * os.dot(ds), os.squaredNorm() - 1.0, min_t);
}

std::optional<double> hitCylinder(const Eigen::Vector3d& o, const Eigen::Vector3d& d,
                                  double radius, double half_height, double min_t) {
  std::optional<double> best;
  auto consider = [&](double t) {
    if (t > min_t && (!best || t < *best)) best = t;
  };
  const double a = d.x() * d.x() + d.y() * d.y();
  const double b = 2.0 * (o.x() * d.x() + o.y() * d.y());
  const double c = o.x() * o.x() + o.y() * o.y() - radius * radius;
  const double discriminant = b * b - 4.0 * a * c;
  if (a > 0.0 && discriminant >= 0.0) {
    const double root = std::sqrt(discriminant);
    for (const double t : {(-b - root) / (2.0 * a), (-b + root) / (2.0 * a)}) {
      if (std::abs(o.z() + t * d.z()) <= half_height) consider(t);
    }
  }
  if (std::abs(d.z()) > 1e-15) {
    for (const double cap : {-half_height, half_height}) {
      const double t = (cap - o.z()) / d.z();
      const Eigen::Vector3d p = o + t * d;
      if (p.x() * p.x() + p.y() * p.y() <= radius * radius) consider(t);
    }
  }
  return best;
}

/// Outward unit normal at the surface point p (local coordinates) of a primitive.
Eigen::Vector3d localNormal(PrimitiveType type, const Eigen::Vector3d& p,
                            const Eigen::Vector3d& h) {
  switch (type) {
    case PrimitiveType::kBox: {
      // The face the point lies on: the axis where it is relatively closest to the face.
      int axis = 0;
      double closest = kInfinity;
      for (int i = 0; i < 3; ++i) {
        const double gap = std::abs(h[i] - std::abs(p[i]));
        if (gap < closest) {
          closest = gap;
          axis = i;
        }
      }
      Eigen::Vector3d n = Eigen::Vector3d::Zero();
      n[axis] = p[axis] < 0.0 ? -1.0 : 1.0;
      return n;
    }
    case PrimitiveType::kEllipsoid:
      return p.cwiseQuotient(h.cwiseProduct(h)).normalized();
    case PrimitiveType::kCylinder: {
      const double radial = std::hypot(p.x(), p.y());
      if (std::abs(h.z() - std::abs(p.z())) < std::abs(h.x() - radial) || radial == 0.0) {
        return Eigen::Vector3d(0.0, 0.0, p.z() < 0.0 ? -1.0 : 1.0);
      }
      return Eigen::Vector3d(p.x() / radial, p.y() / radial, 0.0);
    }
  }
  return Eigen::Vector3d::UnitZ();
}

}  // namespace

Scene::Scene(std::vector<Primitive> primitives) : primitives_(std::move(primitives)) {
  for (const Primitive& primitive : primitives_) {
    Prepared prepared{primitive,
                      Eigen::AngleAxisd(-primitive.yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix(),
                      primitive.half_size.norm()};
    prepared_.push_back(prepared);
  }
}

std::optional<double> Scene::raycast(const Eigen::Vector3d& origin,
                                     const Eigen::Vector3d& direction, double min_t) const {
  const std::optional<RayHit> hit = raycastHit(origin, direction, min_t);
  if (!hit) return std::nullopt;
  return hit->t;
}

std::optional<RayHit> Scene::raycastHit(const Eigen::Vector3d& origin,
                                        const Eigen::Vector3d& direction, double min_t) const {
  std::optional<double> best;
  size_t best_index = 0;
  const double direction_squared = direction.squaredNorm();
  for (size_t index = 0; index < prepared_.size(); ++index) {
    const Prepared& item = prepared_[index];
    // Bounding-sphere rejection: most primitives are nowhere near most rays.
    const Eigen::Vector3d to_center = item.primitive.center - origin;
    const double along = to_center.dot(direction) / direction_squared;
    const Eigen::Vector3d closest = to_center - along * direction;
    if (closest.squaredNorm() > item.bounding_radius * item.bounding_radius) continue;
    if (best && (along - item.bounding_radius / std::sqrt(direction_squared)) > *best) continue;

    const Eigen::Vector3d o = item.world_to_local * (origin - item.primitive.center);
    const Eigen::Vector3d d = item.world_to_local * direction;
    std::optional<double> hit;
    switch (item.primitive.type) {
      case PrimitiveType::kBox:
        hit = hitBox(o, d, item.primitive.half_size, min_t);
        break;
      case PrimitiveType::kEllipsoid:
        hit = hitEllipsoid(o, d, item.primitive.half_size, min_t);
        break;
      case PrimitiveType::kCylinder:
        hit = hitCylinder(o, d, item.primitive.half_size.x(), item.primitive.half_size.z(), min_t);
        break;
    }
    if (hit && (!best || *hit < *best)) {
      best = hit;
      best_index = index;
    }
  }
  if (!best) return std::nullopt;
  RayHit result;
  result.t = *best;
  result.primitive = best_index;
  const Prepared& item = prepared_[best_index];
  const Eigen::Vector3d p =
      item.world_to_local * (origin + *best * direction - item.primitive.center);
  result.normal = item.world_to_local.transpose() *
                  localNormal(item.primitive.type, p, item.primitive.half_size);
  return result;
}

bool Scene::inside(const Eigen::Vector3d& point, double margin) const {
  for (const Prepared& item : prepared_) {
    const Eigen::Vector3d p = item.world_to_local * (point - item.primitive.center);
    const Eigen::Vector3d& h = item.primitive.half_size;
    switch (item.primitive.type) {
      case PrimitiveType::kBox:
        if ((p.cwiseAbs() - h).maxCoeff() < -margin) return true;
        break;
      case PrimitiveType::kEllipsoid:
        if (p.cwiseQuotient(h + Eigen::Vector3d::Constant(-margin)).norm() < 1.0) return true;
        break;
      case PrimitiveType::kCylinder:
        if (std::hypot(p.x(), p.y()) < h.x() - margin && std::abs(p.z()) < h.z() - margin) {
          return true;
        }
        break;
    }
  }
  return false;
}

std::vector<SurfacePoint> Scene::sampleSurface(double spacing) const {
  std::vector<SurfacePoint> points;
  auto add = [&](const Prepared& item, const Eigen::Vector3d& local_point,
                 const Eigen::Vector3d& local_normal) {
    const Eigen::Matrix3d local_to_world = item.world_to_local.transpose();
    const Eigen::Vector3d position = item.primitive.center + local_to_world * local_point;
    if (inside(position, 1e-4)) return;
    points.push_back({position, (local_to_world * local_normal).normalized()});
  };
  for (const Prepared& item : prepared_) {
    const Eigen::Vector3d& h = item.primitive.half_size;
    if (item.primitive.type == PrimitiveType::kBox) {
      for (int axis = 0; axis < 3; ++axis) {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        const int nu = std::max(1, static_cast<int>(std::ceil(2.0 * h[u] / spacing)));
        const int nv = std::max(1, static_cast<int>(std::ceil(2.0 * h[v] / spacing)));
        for (const double side : {-1.0, 1.0}) {
          for (int i = 0; i < nu; ++i) {
            for (int j = 0; j < nv; ++j) {
              Eigen::Vector3d p, n = Eigen::Vector3d::Zero();
              p[axis] = side * h[axis];
              p[u] = -h[u] + 2.0 * h[u] * (i + 0.5) / nu;  // cell centres: no edge points
              p[v] = -h[v] + 2.0 * h[v] * (j + 0.5) / nv;
              n[axis] = side;
              add(item, p, n);
            }
          }
        }
      }
    } else if (item.primitive.type == PrimitiveType::kEllipsoid) {
      const double max_radius = h.maxCoeff();
      const int rings = std::max(4, static_cast<int>(std::ceil(M_PI * max_radius / spacing)));
      for (int i = 0; i <= rings; ++i) {
        const double theta = M_PI * i / rings;
        const int segments = std::max(
            1, static_cast<int>(std::ceil(2.0 * M_PI * max_radius * std::sin(theta) / spacing)));
        for (int j = 0; j < segments; ++j) {
          const double phi = 2.0 * M_PI * j / segments;
          const Eigen::Vector3d unit(std::sin(theta) * std::cos(phi),
                                     std::sin(theta) * std::sin(phi), std::cos(theta));
          add(item, unit.cwiseProduct(h), unit.cwiseQuotient(h));
        }
      }
    } else {
      const double radius = h.x();
      const int segments = std::max(8, static_cast<int>(std::ceil(2.0 * M_PI * radius / spacing)));
      const int stacks = std::max(1, static_cast<int>(std::ceil(2.0 * h.z() / spacing)));
      for (int j = 0; j < segments; ++j) {
        const double phi = 2.0 * M_PI * j / segments;
        const Eigen::Vector3d radial(std::cos(phi), std::sin(phi), 0.0);
        for (int i = 0; i <= stacks; ++i) {
          add(item, radius * radial + Eigen::Vector3d(0, 0, -h.z() + 2.0 * h.z() * i / stacks),
              radial);
        }
      }
      const int rings = std::max(1, static_cast<int>(std::ceil(radius / spacing)));
      for (const double side : {-1.0, 1.0}) {
        add(item, Eigen::Vector3d(0, 0, side * h.z()), Eigen::Vector3d(0, 0, side));
        for (int r = 1; r <= rings; ++r) {
          const double ring_radius = radius * r / rings;
          const int count = std::max(6, static_cast<int>(std::ceil(2.0 * M_PI * ring_radius / spacing)));
          for (int j = 0; j < count; ++j) {
            const double phi = 2.0 * M_PI * j / count;
            add(item,
                Eigen::Vector3d(ring_radius * std::cos(phi), ring_radius * std::sin(phi),
                                side * h.z()),
                Eigen::Vector3d(0, 0, side));
          }
        }
      }
    }
  }
  return points;
}

}  // namespace vicc_tracking::sim
