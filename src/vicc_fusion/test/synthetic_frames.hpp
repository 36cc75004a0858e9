#pragma once
// Synthetic depth levels for the fusion tests: fronto-parallel planes and patches with exact
// normals and Gaussian depth noise, on a small pinhole grid.

#include <random>

#include "vicc_tracking/depth_preprocessing.hpp"

namespace vicc_fusion::test {

inline vicc_tracking::PinholeIntrinsics smallCamera() {
  vicc_tracking::PinholeIntrinsics intrinsics;
  intrinsics.width = 64;
  intrinsics.height = 48;
  intrinsics.fx = intrinsics.fy = 60.f;
  intrinsics.cx = 31.5f;
  intrinsics.cy = 23.5f;
  return intrinsics;
}

/// Depth per pixel: `depth_of(u, v)` metres (<= 0: invalid), plus noise of `sigma` along the
/// ray; normals face the camera (-z), radii as the preprocessing computes them.
template <typename DepthOf>
vicc_tracking::DepthLevel syntheticFrame(const vicc_tracking::PinholeIntrinsics& intrinsics,
                                         DepthOf depth_of, double sigma, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> noise(0.f, static_cast<float>(sigma));
  vicc_tracking::DepthLevel level;
  level.intrinsics = intrinsics;
  const size_t count = static_cast<size_t>(intrinsics.width) * intrinsics.height;
  level.depth = cv::Mat1f(intrinsics.height, intrinsics.width, 0.f);
  level.vertices.assign(count, Eigen::Vector3f::Zero());
  level.normals.assign(count, Eigen::Vector3f::Zero());
  level.radii.assign(count, 0.f);
  for (int v = 0; v < intrinsics.height; ++v) {
    for (int u = 0; u < intrinsics.width; ++u) {
      const float true_depth = static_cast<float>(depth_of(u, v));
      if (true_depth <= 0.f) continue;
      const float z = true_depth + noise(rng);
      const size_t i = static_cast<size_t>(v) * intrinsics.width + u;
      level.vertices[i] = Eigen::Vector3f((u - intrinsics.cx) * z / intrinsics.fx,
                                          (v - intrinsics.cy) * z / intrinsics.fy, z);
      level.normals[i] = -Eigen::Vector3f::UnitZ();
      level.radii[i] = std::sqrt(2.f) * 0.5f * z / intrinsics.fx;
      level.depth(v, u) = z;
      ++level.valid_vertices;
      ++level.valid_normals;
    }
  }
  return level;
}

inline vicc_tracking::DepthLevel planeFrame(double depth, double sigma, unsigned seed) {
  return syntheticFrame(
      smallCamera(), [depth](int, int) { return depth; }, sigma, seed);
}

}  // namespace vicc_fusion::test
