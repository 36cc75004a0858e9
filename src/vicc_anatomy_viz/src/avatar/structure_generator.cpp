#include "vicc_anatomy_viz/avatar/structure_generator.hpp"

#include <Eigen/Geometry>

#include <cmath>

#include "section_rings.hpp"
#include "vicc_anatomy_viz/avatar/cross_section.hpp"
#include "vicc_anatomy_viz/avatar/mesh_geometry.hpp"
#include "vicc_anatomy_viz/errors.hpp"

namespace vicc_anatomy_viz::avatar {

namespace {

constexpr int kStations = 18;  // along the axis, the two ends are the structure's tips
constexpr int kBisectionSteps = 14;
constexpr float kMaxRingGrowth = 1.2f;

/// One station: the plane across the bone, the skin's contour around the axis in it and the
/// structure's full-size ring there.
struct Station {
  SectionPlane plane;
  SectionLoop skin_section;
  SectionRing ring;
};

Station stationAt(const TriangleMesh& skin, const BoneFrame& bone, const GeneratedShape& shape,
                  float fraction, const std::string& what) {
  Station station;
  const float tilt = shape.tilt * static_cast<float>(M_PI) / 180.0f;
  const Eigen::Vector3f normal = std::cos(tilt) * bone.axis - std::sin(tilt) * bone.anterior;
  station.plane = SectionPlane::through(bone.at(fraction), normal, bone.anterior);
  const std::vector<SectionLoop> loops = sliceMesh(skin, station.plane);
  const SectionLoop* loop = loopContaining(loops, Eigen::Vector2f::Zero());
  if (!loop) {
    throw ConfigError(what + ": the " + shape.bone + " axis leaves the skin at " +
                      std::to_string(fraction));
  }
  station.skin_section = *loop;
  station.ring = sectionRing(station.skin_section, station.plane, bone, shape);
  return station;
}

/// The belly profile at t in [0, 1]: sin(pi t) to the end's exponent.
float profile(const GeneratedShape& shape, float t) {
  const float exponent = t < 0.5f ? shape.profile_proximal : shape.profile_distal;
  return std::pow(std::sin(static_cast<float>(M_PI) * t), exponent);
}

/// The largest scale up to `full` at which the station's ring lies `margin` inside the skin's
/// section (bisection: a continuous result, so that left and right stay mirror images).
float fittedScale(const Station& station, float full, float margin) {
  const auto fits = [&](float scale) {
    for (const Eigen::Vector2f& point : station.ring.scaled(scale)) {
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
/// per station in absolute size), so that the structure narrows smoothly without a notch.
void smoothScales(std::vector<float>& scales, const std::vector<Station>& stations) {
  const auto size = [&](std::size_t k) { return scales[k] * stations[k].ring.size; };
  const auto limit = [&](std::size_t k, std::size_t neighbour) {
    if (stations[k].ring.size <= 0) return;
    scales[k] = std::min(scales[k], size(neighbour) * kMaxRingGrowth / stations[k].ring.size);
  };
  for (std::size_t k = 2; k + 1 < scales.size(); ++k) limit(k, k - 1);
  for (std::size_t k = scales.size() - 2; k-- > 1;) limit(k, k + 1);
}

void addTriangle(TriangleMesh& mesh, int a, int b, int c) { mesh.triangles.emplace_back(a, b, c); }

/// Vertex 0 is the proximal tip, then `rings` rings of `points` vertices, then the distal tip.
void stitchRings(TriangleMesh& mesh, int rings, int points) {
  const int distal_tip = 1 + rings * points;
  const auto ring_vertex = [points](int ring, int k) { return 1 + ring * points + k % points; };
  for (int k = 0; k < points; ++k) {
    addTriangle(mesh, 0, ring_vertex(0, k + 1), ring_vertex(0, k));
    addTriangle(mesh, distal_tip, ring_vertex(rings - 1, k), ring_vertex(rings - 1, k + 1));
    for (int r = 0; r + 1 < rings; ++r) {
      addTriangle(mesh, ring_vertex(r, k), ring_vertex(r, k + 1), ring_vertex(r + 1, k + 1));
      addTriangle(mesh, ring_vertex(r, k), ring_vertex(r + 1, k + 1), ring_vertex(r + 1, k));
    }
  }
}

}  // namespace

TriangleMesh generateShape(const TriangleMesh& skin, const BodyLandmarks& landmarks,
                           const GeneratedShape& shape, Side side, float margin,
                           const std::string& what) {
  const BoneFrame bone = landmarks.bone(shape.bone, side);
  std::vector<Station> stations;
  std::vector<float> scales;
  for (int s = 0; s <= kStations; ++s) {
    const float t = static_cast<float>(s) / kStations;
    stations.push_back(
        stationAt(skin, bone, shape, shape.from + t * (shape.to - shape.from), what));
    scales.push_back(fittedScale(stations.back(), profile(shape, t), margin));
  }
  smoothScales(scales, stations);
  TriangleMesh mesh;
  for (int s = 0; s <= kStations; ++s) {
    const Station& station = stations[s];
    if (s == 0 || s == kStations) {
      mesh.vertices.push_back(station.plane.lift(station.ring.centre));
      continue;
    }
    for (const Eigen::Vector2f& point : station.ring.scaled(scales[s])) {
      mesh.vertices.push_back(station.plane.lift(point));
    }
  }
  stitchRings(mesh, kStations - 1, ringPointCount(shape.section));
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
