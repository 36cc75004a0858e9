#pragma once
// Memory order of the model: every per-frame pass (index map, correspondence search, model
// prediction) visits the surfels seen by the camera, and does so at random addresses unless
// the array is laid out the way the camera sees it. Sorting by the pixel a surfel projects to
// turns those cache misses into sequential access; the camera moves little between frames, so
// an occasional re-sort keeps the order useful.

#include <vector>

#include <Eigen/Geometry>

#include "vicc_fusion/surfel.hpp"
#include "vicc_tracking/depth_preprocessing.hpp"

namespace vicc_fusion {

/// Reorders `surfels` (stable counting sort) by the row-major pixel they project to from
/// camera_pose = T_map_camera; surfels outside the image or behind the camera keep their
/// relative order after all others. Only the order changes, never the content.
class SurfelOrder {
 public:
  void sortByPixel(SurfelVector& surfels, const Eigen::Isometry3f& camera_pose,
                   const vicc_tracking::PinholeIntrinsics& intrinsics);

 private:
  // Scratch kept across calls: a sort every few frames must not allocate megabytes each time.
  std::vector<int> keys_;
  std::vector<int> bucket_start_;
  SurfelVector sorted_;
};

}  // namespace vicc_fusion
