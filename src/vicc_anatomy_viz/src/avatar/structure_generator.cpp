#include "vicc_anatomy_viz/avatar/structure_generator.hpp"

#include <Eigen/Geometry>

#include <cmath>

#include "vicc_anatomy_viz/avatar/cross_section.hpp"
#include "vicc_anatomy_viz/avatar/mesh_geometry.hpp"
#include "vicc_anatomy_viz/errors.hpp"

namespace vicc_anatomy_viz::avatar {

namespace {

constexpr int kStations = 18;  // along the axis, the two ends are the spindle's tips
constexpr int kRingPoints = 14;
constexpr float kProfileExponent = 0.6f;  // < 1: a full belly tapering into short tendons
constexpr int kBisectionSteps = 14;
constexpr float kMaxRingGrowth = 1.2f;

/// One station of the spindle: the skin cross-section and the ring placed in it.
struct Station {
  SectionPlane plane;
  SectionLoop skin_section;  ///< the skin's contour around the axis
  Eigen::Vector2f centre;    ///< the ring centre in plane coordinates
  Eigen::Vector2f radial;    ///< unit, towards the azimuth
  float skin_radius = 0;     ///< axis to skin along `radial`
};

Station stationAt(const TriangleMesh& skin, const BoneFrame& bone, const GeneratedShape& shape,
                  float fraction, const std::string& what) {
  Station station;
  station.plane = SectionPlane::through(bone.at(fraction), bone.axis, bone.anterior);
  const std::vector<SectionLoop> loops = sliceMesh(skin, station.plane);
  const SectionLoop* loop = loopContaining(loops, Eigen::Vector2f::Zero());
  if (!loop) {
    throw ConfigError(what + ": the " + shape.bone + " axis leaves the skin at " +
                      std::to_string(fraction));
  }
  station.skin_section = *loop;
  const Eigen::Vector3f direction = bone.direction(shape.azimuth);
  station.radial =
      Eigen::Vector2f(direction.dot(station.plane.u), direction.dot(station.plane.v)).normalized();
  station.skin_radius = loop->rayDistance(Eigen::Vector2f::Zero(), station.radial).value_or(0);
  station.centre = shape.depth * station.skin_radius * station.radial;
  return station;
}

/// The ring of a station with radial half-thickness `radial_half`, in plane coordinates.
std::vector<Eigen::Vector2f> ringPoints(const Station& station, const GeneratedShape& shape,
                                        float radial_half) {
  const Eigen::Vector2f tangential(-station.radial.y(), station.radial.x());
  std::vector<Eigen::Vector2f> ring(kRingPoints);
  for (int k = 0; k < kRingPoints; ++k) {
    const float angle = 2.0f * static_cast<float>(M_PI) * k / kRingPoints;
    ring[k] = station.centre + radial_half * std::cos(angle) * station.radial +
              shape.width * radial_half * std::sin(angle) * tangential;
  }
  return ring;
}

/// The largest radial half-thickness up to `full` whose ring lies `margin` inside the skin's
/// section (bisection: a continuous result, so that left and right stay mirror images).
float fittedHalfThickness(const Station& station, const GeneratedShape& shape, float full,
                          float margin) {
  const auto fits = [&](float radial_half) {
    for (const Eigen::Vector2f& point : ringPoints(station, shape, radial_half)) {
      if (!station.skin_section.contains(point) ||
          station.skin_section.distanceToContour(point) < margin) {
        return false;
      }
    }
    return true;
  };
  if (fits(full)) return full;
  float low = 0, high = full;
  for (int step = 0; step < kBisectionSteps; ++step) {
    const float middle = (low + high) / 2;
    (fits(middle) ? low : high) = middle;
  }
  return low;
}

/// Where the skin forced a ring smaller, its neighbours shrink too (by at most kMaxRingGrowth
/// per station), so that the muscle narrows smoothly instead of showing a notch.
void smoothRadii(std::vector<float>& radii) {
  for (std::size_t k = 2; k + 1 < radii.size(); ++k) {
    radii[k] = std::min(radii[k], radii[k - 1] * kMaxRingGrowth);
  }
  for (std::size_t k = radii.size() - 2; k-- > 1;) {
    radii[k] = std::min(radii[k], radii[k + 1] * kMaxRingGrowth);
  }
}

void addTriangle(TriangleMesh& mesh, int a, int b, int c) { mesh.triangles.emplace_back(a, b, c); }

}  // namespace

TriangleMesh generateSpindle(const TriangleMesh& skin, const BodyLandmarks& landmarks,
                             const GeneratedShape& shape, Side side, float margin,
                             const std::string& what) {
  const BoneFrame bone = landmarks.bone(shape.bone, side);
  std::vector<Station> stations;
  std::vector<float> radii;
  for (int s = 0; s <= kStations; ++s) {
    const float t = static_cast<float>(s) / kStations;
    stations.push_back(
        stationAt(skin, bone, shape, shape.from + t * (shape.to - shape.from), what));
    const float profile = std::pow(std::sin(static_cast<float>(M_PI) * t), kProfileExponent);
    const float full = shape.thickness * stations.back().skin_radius * profile;
    radii.push_back(fittedHalfThickness(stations.back(), shape, full, margin));
  }
  smoothRadii(radii);
  TriangleMesh mesh;
  for (int s = 0; s <= kStations; ++s) {
    const Station& station = stations[s];
    if (s == 0 || s == kStations) {
      mesh.vertices.push_back(station.plane.lift(station.centre));
      continue;
    }
    for (const Eigen::Vector2f& point : ringPoints(station, shape, radii[s])) {
      mesh.vertices.push_back(station.plane.lift(point));
    }
  }
  // Vertex 0 is the proximal tip, then (kStations - 1) rings, then the distal tip.
  const int rings = kStations - 1;
  const int distal_tip = 1 + rings * kRingPoints;
  const auto ring_vertex = [](int ring, int k) { return 1 + ring * kRingPoints + k % kRingPoints; };
  for (int k = 0; k < kRingPoints; ++k) {
    addTriangle(mesh, 0, ring_vertex(0, k + 1), ring_vertex(0, k));
    addTriangle(mesh, distal_tip, ring_vertex(rings - 1, k), ring_vertex(rings - 1, k + 1));
    for (int r = 0; r + 1 < rings; ++r) {
      addTriangle(mesh, ring_vertex(r, k), ring_vertex(r, k + 1), ring_vertex(r + 1, k + 1));
      addTriangle(mesh, ring_vertex(r, k), ring_vertex(r + 1, k + 1), ring_vertex(r + 1, k));
    }
  }
  orientOutwards(mesh);
  mesh.normals = vertexNormals(mesh);
  return mesh;
}

SkinProxy placeProxy(const TriangleMesh& skin, const BodyLandmarks& landmarks,
                     const ProxyPlacement& placement, Side side, const std::string& what) {
  const BoneFrame bone = landmarks.bone(placement.bone, side);
  const float elevation = placement.elevation * static_cast<float>(M_PI) / 180.0f;
  const Eigen::Vector3f direction =
      std::cos(elevation) * bone.direction(placement.azimuth) + std::sin(elevation) * bone.axis;
  const std::optional<Eigen::Vector3f> hit = castRay(skin, bone.at(placement.at), direction);
  if (!hit) throw ConfigError(what + ": the proxy ray finds no skin");
  SkinProxy proxy;
  proxy.centre = *hit;
  proxy.normal = skin.normals[nearestVertex(skin, *hit)];
  proxy.radius = placement.radius;
  return proxy;
}

}  // namespace vicc_anatomy_viz::avatar
