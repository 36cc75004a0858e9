#include "vicc_fusion/model_accuracy.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <pcl/io/ply_io.h>
#include <pcl/kdtree/kdtree_flann.h>

namespace vicc_fusion {

pcl::PointCloud<pcl::PointNormal> loadTruthSurface(const std::string& path) {
  pcl::PointCloud<pcl::PointNormal> cloud;
  if (pcl::io::loadPLYFile(path, cloud) != 0) throw std::runtime_error("cannot read " + path);
  if (cloud.empty()) throw std::runtime_error(path + " holds no points");
  return cloud;
}

ModelAccuracy evaluateModel(const SurfelVector& surfels,
                            const pcl::PointCloud<pcl::PointNormal>& truth,
                            const Eigen::Isometry3d& truth_from_model, double completeness_radius,
                            double region_margin) {
  ModelAccuracy accuracy;
  accuracy.truth_points = truth.size();
  accuracy.completeness_radius = completeness_radius;
  if (surfels.empty() || truth.empty()) return accuracy;

  pcl::PointCloud<pcl::PointXYZ>::Ptr model(new pcl::PointCloud<pcl::PointXYZ>);
  model->reserve(surfels.size());
  const Eigen::Isometry3f transform = truth_from_model.cast<float>();
  for (const Surfel& s : surfels) {
    pcl::PointXYZ point;
    point.getVector3fMap() = transform * s.position;
    model->push_back(point);
  }
  pcl::PointCloud<pcl::PointNormal>::Ptr truth_ptr(new pcl::PointCloud<pcl::PointNormal>(truth));
  pcl::KdTreeFLANN<pcl::PointNormal> truth_tree;
  truth_tree.setInputCloud(truth_ptr);

  std::vector<int> index(1);
  std::vector<float> squared(1);
  std::vector<double> distances;
  distances.reserve(model->size());
  for (const pcl::PointXYZ& point : *model) {
    pcl::PointNormal query;
    query.getVector3fMap() = point.getVector3fMap();
    if (truth_tree.nearestKSearch(query, 1, index, squared) < 1) continue;
    const pcl::PointNormal& nearest = truth[index[0]];
    const Eigen::Vector3f offset = point.getVector3fMap() - nearest.getVector3fMap();
    const double euclidean = offset.norm();
    if (euclidean > region_margin) {
      ++accuracy.surfels_outside;
      continue;
    }
    // Point-to-plane near the sampled surface; between samples of a curved surface or at an
    // edge the Euclidean distance is the honest figure.
    const double to_plane = std::abs(offset.dot(nearest.getNormalVector3fMap()));
    distances.push_back(euclidean < 0.005 ? to_plane : euclidean);
  }
  accuracy.surfels = distances.size();
  if (distances.empty()) return accuracy;
  double sum = 0.0;
  for (const double d : distances) sum += d;
  accuracy.mean_distance = sum / distances.size();
  std::sort(distances.begin(), distances.end());
  accuracy.median_distance = distances[distances.size() / 2];
  accuracy.p95_distance = distances[std::min(distances.size() - 1, distances.size() * 95 / 100)];

  pcl::KdTreeFLANN<pcl::PointXYZ> model_tree;
  model_tree.setInputCloud(model);
  size_t covered = 0;
  const float radius_squared = static_cast<float>(completeness_radius * completeness_radius);
  for (const pcl::PointNormal& point : truth) {
    pcl::PointXYZ query;
    query.getVector3fMap() = point.getVector3fMap();
    if (model_tree.nearestKSearch(query, 1, index, squared) >= 1 && squared[0] <= radius_squared) {
      ++covered;
    }
  }
  accuracy.completeness = static_cast<double>(covered) / truth.size();
  return accuracy;
}

}  // namespace vicc_fusion
