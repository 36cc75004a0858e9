#pragma once
// Reconstruction accuracy against a known surface (the simulator's visible true surface):
// how far the stable surfels lie from it, and how much of it they cover.

#include <string>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Geometry>

#include "vicc_fusion/surfel.hpp"

namespace vicc_fusion {

struct ModelAccuracy {
  size_t surfels = 0;          ///< evaluated: within region_margin of the true surface
  size_t surfels_outside = 0;  ///< further from it: surface the reference does not cover
  size_t truth_points = 0;
  double mean_distance = 0.0;    ///< m, surfel to true surface
  double median_distance = 0.0;  ///< m
  double p95_distance = 0.0;     ///< m
  double completeness = 0.0;     ///< share of true points within completeness_radius of a surfel
  double completeness_radius = 0.0;
};

/// Binary/ASCII PLY with x y z nx ny nz. Throws std::runtime_error naming the file.
pcl::PointCloud<pcl::PointNormal> loadTruthSurface(const std::string& path);

/// `truth_from_model` maps the model's map frame into the truth's. The reference is the
/// surface the camera saw at close range (vicc_make_bag --surface); surfels further than
/// `region_margin` from it lie on surface it does not cover (far walls) and are counted, not
/// measured. The distance is point-to-plane against the nearest true sample (its normal),
/// which removes the sampling spacing from the figure; completeness is Euclidean.
ModelAccuracy evaluateModel(const SurfelVector& surfels,
                            const pcl::PointCloud<pcl::PointNormal>& truth,
                            const Eigen::Isometry3d& truth_from_model,
                            double completeness_radius = 0.005, double region_margin = 0.02);

}  // namespace vicc_fusion
