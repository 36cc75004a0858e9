#include "section_rings.hpp"

#include <algorithm>
#include <cmath>

namespace vicc_anatomy_viz::avatar {

namespace {

constexpr int kEllipsePoints = 14;
constexpr int kSectorArcPoints = 10;  // on the outer arc, and as many on the inner one
constexpr int kCavityPoints = 32;
constexpr float kPi = static_cast<float>(M_PI);

/// The unit in-plane direction of a bone azimuth.
Eigen::Vector2f planeDirection(const SectionPlane& plane, const BoneFrame& bone, float azimuth) {
  const Eigen::Vector3f direction = bone.direction(azimuth);
  return Eigen::Vector2f(direction.dot(plane.u), direction.dot(plane.v)).normalized();
}

float skinDistance(const SectionLoop& skin, const Eigen::Vector2f& from,
                   const Eigen::Vector2f& direction) {
  return skin.rayDistance(from, direction).value_or(0.f);
}

SectionRing ellipseRing(const SectionLoop& skin, const SectionPlane& plane, const BoneFrame& bone,
                        const GeneratedShape& shape) {
  const Eigen::Vector2f radial = planeDirection(plane, bone, shape.azimuth);
  const Eigen::Vector2f tangential(-radial.y(), radial.x());
  const float skin_radius = skinDistance(skin, Eigen::Vector2f::Zero(), radial);
  SectionRing ring;
  ring.centre = shape.depth * skin_radius * radial;
  ring.size = shape.thickness * skin_radius;
  for (int k = 0; k < kEllipsePoints; ++k) {
    const float angle = 2.0f * kPi * k / kEllipsePoints;
    ring.points.push_back(ring.centre + ring.size * std::cos(angle) * radial +
                          shape.width * ring.size * std::sin(angle) * tangential);
  }
  return ring;
}

/// Outer arc from one edge of the sector to the other, then the inner arc back.
SectionRing sectorRing(const SectionLoop& skin, const SectionPlane& plane, const BoneFrame& bone,
                       const GeneratedShape& shape) {
  SectionRing ring;
  std::vector<Eigen::Vector2f> inner;
  for (int k = 0; k < kSectorArcPoints; ++k) {
    const float azimuth =
        shape.azimuth - shape.span / 2 + shape.span * k / static_cast<float>(kSectorArcPoints - 1);
    const Eigen::Vector2f direction = planeDirection(plane, bone, azimuth);
    const float reach = skinDistance(skin, Eigen::Vector2f::Zero(), direction);
    ring.points.push_back(shape.outer * reach * direction);
    inner.push_back(shape.inner * reach * direction);
  }
  ring.points.insert(ring.points.end(), inner.rbegin(), inner.rend());
  const Eigen::Vector2f middle = planeDirection(plane, bone, shape.azimuth);
  const float reach = skinDistance(skin, Eigen::Vector2f::Zero(), middle);
  ring.centre = (shape.inner + shape.outer) / 2 * reach * middle;
  ring.size = (shape.outer - shape.inner) / 2 * reach;
  return ring;
}

/// Moves points onto the `half` side of the midsagittal plane (world y = 0), at least
/// `fissure` / 2 from it: a flat medial face, as a hemisphere has against the falx.
void keepHalf(std::vector<Eigen::Vector2f>& points, const SectionPlane& plane, Side half,
              float fissure) {
  const float sign = half == Side::kLeft ? 1.f : -1.f;
  const Eigen::Vector2f lateral(plane.u.y(), plane.v.y());  // d(world y) / d(plane coordinate)
  if (lateral.squaredNorm() < 1e-6f) return;                // the plane contains no y direction
  for (Eigen::Vector2f& point : points) {
    const float y = plane.lift(point).y();
    const float missing = fissure / 2 - sign * y;
    if (missing > 0) point += sign * missing * lateral / lateral.squaredNorm();
  }
}

/// The skin's section shrunk by `inset` (sampled by rays from its centroid), the `half` of it,
/// resampled by rays from its own centroid so the points spread evenly round its outline.
SectionRing cavityRing(const SectionLoop& skin, const SectionPlane& plane,
                       const GeneratedShape& shape) {
  const auto sampled = [](const SectionLoop& loop, float inset) {
    std::vector<Eigen::Vector2f> points;
    for (int k = 0; k < kCavityPoints; ++k) {
      const float angle = 2.0f * kPi * k / kCavityPoints;
      const Eigen::Vector2f direction(std::cos(angle), std::sin(angle));
      const float reach = std::max(skinDistance(loop, loop.centroid, direction) - inset, 0.f);
      points.push_back(loop.centroid + reach * direction);
    }
    return points;
  };
  std::vector<Eigen::Vector2f> points = sampled(skin, shape.inset);
  if (shape.half != Side::kNone) {
    keepHalf(points, plane, shape.half, shape.fissure);
    points = sampled(SectionLoop::fromPoints(points), 0.f);
  }
  const SectionLoop outline = SectionLoop::fromPoints(points);
  SectionRing ring;
  ring.points = points;
  ring.centre = outline.centroid;
  ring.size = std::sqrt(static_cast<float>(outline.area) / kPi);
  return ring;
}

}  // namespace

std::vector<Eigen::Vector2f> SectionRing::scaled(float scale) const {
  std::vector<Eigen::Vector2f> result;
  result.reserve(points.size());
  for (const Eigen::Vector2f& point : points) result.push_back(centre + scale * (point - centre));
  return result;
}

int ringPointCount(SectionShape section) {
  switch (section) {
    case SectionShape::kSector:
      return 2 * kSectorArcPoints;
    case SectionShape::kCavity:
      return kCavityPoints;
    case SectionShape::kEllipse:
      break;
  }
  return kEllipsePoints;
}

SectionRing sectionRing(const SectionLoop& skin, const SectionPlane& plane, const BoneFrame& bone,
                        const GeneratedShape& shape) {
  switch (shape.section) {
    case SectionShape::kSector:
      return sectorRing(skin, plane, bone, shape);
    case SectionShape::kCavity:
      return cavityRing(skin, plane, shape);
    case SectionShape::kEllipse:
      break;
  }
  return ellipseRing(skin, plane, bone, shape);
}

}  // namespace vicc_anatomy_viz::avatar
