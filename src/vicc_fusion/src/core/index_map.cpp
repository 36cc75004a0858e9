#include "vicc_fusion/index_map.hpp"

#include <cmath>

namespace vicc_fusion {

void IndexMap::render(const SurfelVector& surfels, const Eigen::Isometry3f& camera_pose,
                      const vicc_tracking::PinholeIntrinsics& intrinsics, int factor) {
  const size_t cell_count =
      static_cast<size_t>(intrinsics.width) * intrinsics.height * factor * factor;
  if (factor != factor_ || intrinsics.width != width_ || cells_.size() != cell_count) {
    cells_.assign(cell_count, kEmpty);
  } else {
    for (const size_t cell : occupied_) cells_[cell] = kEmpty;  // most cells were never used
  }
  occupied_.clear();
  factor_ = factor;
  width_ = intrinsics.width;

  // Pixel u covers [u - 0.5, u + 0.5) in the pinhole convention (centres at integers); its
  // cells start at factor*u, so a camera coordinate x maps to cell floor(factor*(x+0.5)).
  const float fx = intrinsics.fx * factor, fy = intrinsics.fy * factor;
  const float cx = (intrinsics.cx + 0.5f) * factor, cy = (intrinsics.cy + 0.5f) * factor;
  const int cols = intrinsics.width * factor, rows = intrinsics.height * factor;
  const Eigen::Isometry3f map_to_camera = camera_pose.inverse();
  const Eigen::Matrix3f rotation = map_to_camera.linear();
  const Eigen::Vector3f translation = map_to_camera.translation();
  depth_row_ = rotation.row(2).transpose();
  depth_offset_ = translation.z();
  const int cells_per_pixel = factor * factor;
  for (size_t i = 0; i < surfels.size(); ++i) {
    const Eigen::Vector3f p = rotation * surfels[i].position + translation;
    if (p.z() <= 0.f) continue;
    const float inv_z = 1.f / p.z();
    const float x = fx * p.x() * inv_z + cx;
    const float y = fy * p.y() * inv_z + cy;
    // Bounds checked in float: a surfel near the camera plane projects beyond the int range,
    // where the cast is undefined. Inside them, truncation is floor.
    if (!(x >= 0.f && y >= 0.f && x < cols && y < rows)) continue;
    const int cell_u = static_cast<int>(x);
    const int cell_v = static_cast<int>(y);
    const int u = cell_u / factor, v = cell_v / factor;
    const size_t cell = (static_cast<size_t>(v) * width_ + u) * cells_per_pixel +
                        (cell_v - v * factor) * factor + (cell_u - u * factor);
    int& occupant = cells_[cell];
    if (occupant == kEmpty) {
      occupant = static_cast<int>(i);
      occupied_.push_back(cell);
    } else if (p.z() < depthOf(surfels[occupant])) {
      occupant = static_cast<int>(i);
    }
  }
}

}  // namespace vicc_fusion
