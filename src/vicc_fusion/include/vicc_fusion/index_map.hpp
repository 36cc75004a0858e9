#pragma once
// The supersampled index map of Keller et al.: every surfel projected into a grid with
// `factor`x`factor` cells per camera pixel, so that the cells of one pixel list the surfels
// along its ray (at most one per cell, the nearest).

#include <vector>

#include <Eigen/Geometry>

#include "vicc_fusion/surfel.hpp"
#include "vicc_tracking/depth_preprocessing.hpp"

namespace vicc_fusion {

class IndexMap {
 public:
  static constexpr int kEmpty = -1;

  /// Projects all surfels seen from camera_pose = T_map_camera into the pixel grid of
  /// `intrinsics`, supersampled by `factor`.
  void render(const SurfelVector& surfels, const Eigen::Isometry3f& camera_pose,
              const vicc_tracking::PinholeIntrinsics& intrinsics, int factor);

  int factor() const { return factor_; }
  int cellsPerPixel() const { return factor_ * factor_; }
  /// The factor*factor cells of pixel (u, v), contiguous (one cache line at factor 4):
  /// surfel indices or kEmpty.
  const int* pixelCells(int u, int v) const {
    return &cells_[(static_cast<size_t>(v) * width_ + u) * cellsPerPixel()];
  }
  /// Camera-frame depth of a surfel, as the map was rendered.
  float depthOf(const Surfel& surfel) const {
    return depth_row_.dot(surfel.position) + depth_offset_;
  }

 private:
  int factor_ = 1;
  int width_ = 0;
  std::vector<int> cells_;
  std::vector<size_t> occupied_;  ///< cells written by the last render, to clear them cheaply
  Eigen::Vector3f depth_row_ = Eigen::Vector3f::UnitZ();
  float depth_offset_ = 0.f;
};

}  // namespace vicc_fusion
