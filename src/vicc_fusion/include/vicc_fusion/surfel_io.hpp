#pragma once
// Export of the surfel model: binary PLY with normals, radius and confidence (pcl::PointSurfel
// fields; MeshLab and CloudCompare read it), and a surface mesh from the stable surfels.

#include <string>

#include <pcl/PolygonMesh.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "vicc_fusion/surfel.hpp"

namespace vicc_fusion {

pcl::PointCloud<pcl::PointSurfel> toPointCloud(const SurfelVector& surfels);
SurfelVector fromPointCloud(const pcl::PointCloud<pcl::PointSurfel>& cloud);

/// Throw std::runtime_error naming the file on failure.
void saveSurfelsPly(const std::string& path, const SurfelVector& surfels);
SurfelVector loadSurfelsPly(const std::string& path);

struct MeshConfig {
  double search_radius = 0.015;  ///< m; longest triangle edge
  double max_neighbour_distance_factor = 2.5;
  int max_neighbours = 60;
};

/// Greedy projection triangulation (PCL) of the surfels with their normals.
pcl::PolygonMesh meshSurfels(const SurfelVector& surfels, const MeshConfig& config = {});
void saveMeshPly(const std::string& path, const pcl::PolygonMesh& mesh);

}  // namespace vicc_fusion
