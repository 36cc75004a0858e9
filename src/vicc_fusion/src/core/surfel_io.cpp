#include "vicc_fusion/surfel_io.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <pcl/conversions.h>
#include <pcl/io/ply_io.h>
#include <pcl/search/kdtree.h>
#include <pcl/surface/gp3.h>

namespace vicc_fusion {

namespace {

/// The 99th percentile of the surfels' intensities (0 if none has one): the PLY's gray is
/// stretched to it, since a ToF amplitude uses a small part of its range (viewers would show
/// a black model) and a few specular highlights should not set the scale.
float brightIntensity(const SurfelVector& surfels) {
  std::vector<float> values;
  for (const Surfel& s : surfels) {
    if (s.hasIntensity()) values.push_back(s.intensity);
  }
  if (values.empty()) return 0.f;
  const auto bright = values.begin() + static_cast<std::ptrdiff_t>(values.size() * 99 / 100);
  std::nth_element(values.begin(), bright, values.end());
  return *bright;
}

}  // namespace

pcl::PointCloud<pcl::PointSurfel> toPointCloud(const SurfelVector& surfels) {
  const float bright = brightIntensity(surfels);
  pcl::PointCloud<pcl::PointSurfel> cloud;
  cloud.reserve(surfels.size());
  for (const Surfel& s : surfels) {
    pcl::PointSurfel point;
    point.getVector3fMap() = s.position;
    point.getNormalVector3fMap() = s.normal;
    point.radius = s.radius;
    point.confidence = s.confidence;
    point.curvature = 0.f;
    // Gray from the intensity when there is one (viewers show it), white otherwise.
    const float gray =
        s.hasIntensity() ? (bright > 0.f ? std::clamp(s.intensity / bright, 0.f, 1.f) : 0.f) : 1.f;
    point.r = point.g = point.b = static_cast<std::uint8_t>(std::lround(gray * 255.f));
    point.a = 255;
    cloud.push_back(point);
  }
  return cloud;
}

SurfelVector fromPointCloud(const pcl::PointCloud<pcl::PointSurfel>& cloud) {
  SurfelVector surfels;
  surfels.reserve(cloud.size());
  for (const pcl::PointSurfel& point : cloud) {
    Surfel s;
    s.position = point.getVector3fMap();
    s.normal = point.getNormalVector3fMap();
    s.radius = point.radius;
    s.confidence = point.confidence;
    if (!s.position.allFinite() || !s.normal.allFinite() || !std::isfinite(s.radius)) {
      throw std::runtime_error("surfel cloud holds a non-finite point");
    }
    surfels.push_back(s);
  }
  return surfels;
}

void saveSurfelsPly(const std::string& path, const SurfelVector& surfels) {
  const auto cloud = toPointCloud(surfels);
  if (cloud.empty()) {
    throw std::runtime_error("cannot write " + path + ": the model has no surfels");
  }
  if (pcl::io::savePLYFileBinary(path, cloud) != 0) {
    throw std::runtime_error("cannot write " + path);
  }
}

SurfelVector loadSurfelsPly(const std::string& path) {
  pcl::PointCloud<pcl::PointSurfel> cloud;
  if (pcl::io::loadPLYFile(path, cloud) != 0) throw std::runtime_error("cannot read " + path);
  return fromPointCloud(cloud);
}

pcl::PolygonMesh meshSurfels(const SurfelVector& surfels, const MeshConfig& config) {
  pcl::PointCloud<pcl::PointNormal>::Ptr cloud(new pcl::PointCloud<pcl::PointNormal>);
  cloud->reserve(surfels.size());
  for (const Surfel& s : surfels) {
    pcl::PointNormal point;
    point.getVector3fMap() = s.position;
    point.getNormalVector3fMap() = s.normal;
    cloud->push_back(point);
  }
  pcl::PolygonMesh mesh;
  if (cloud->size() < 3) return mesh;
  pcl::search::KdTree<pcl::PointNormal>::Ptr tree(new pcl::search::KdTree<pcl::PointNormal>);
  tree->setInputCloud(cloud);
  pcl::GreedyProjectionTriangulation<pcl::PointNormal> triangulation;
  triangulation.setSearchRadius(config.search_radius);
  triangulation.setMu(config.max_neighbour_distance_factor);
  triangulation.setMaximumNearestNeighbors(config.max_neighbours);
  triangulation.setMaximumSurfaceAngle(M_PI / 4);
  triangulation.setMinimumAngle(M_PI / 18);
  triangulation.setMaximumAngle(2 * M_PI / 3);
  triangulation.setNormalConsistency(true);  // surfel normals are oriented (face the camera)
  triangulation.setInputCloud(cloud);
  triangulation.setSearchMethod(tree);
  triangulation.reconstruct(mesh);
  return mesh;
}

void saveMeshPly(const std::string& path, const pcl::PolygonMesh& mesh) {
  if (mesh.polygons.empty()) throw std::runtime_error("cannot write " + path + ": empty mesh");
  if (pcl::io::savePLYFileBinary(path, mesh) != 0) throw std::runtime_error("cannot write " + path);
}

}  // namespace vicc_fusion
