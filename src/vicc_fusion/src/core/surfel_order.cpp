#include "vicc_fusion/surfel_order.hpp"

#include <algorithm>

namespace vicc_fusion {

void SurfelOrder::sortByPixel(SurfelVector& surfels, const Eigen::Isometry3f& camera_pose,
                              const vicc_tracking::PinholeIntrinsics& intrinsics) {
  const int width = intrinsics.width, height = intrinsics.height;
  const int outside = width * height;  // the last bucket: not in view
  const Eigen::Isometry3f map_to_camera = camera_pose.inverse();
  const Eigen::Matrix3f rotation = map_to_camera.linear();
  const Eigen::Vector3f translation = map_to_camera.translation();

  keys_.resize(surfels.size());
  bucket_start_.assign(static_cast<size_t>(outside) + 2, 0);
  for (size_t i = 0; i < surfels.size(); ++i) {
    const Eigen::Vector3f p = rotation * surfels[i].position + translation;
    int key = outside;
    if (p.z() > 0.f) {
      const float inv_z = 1.f / p.z();
      const float u = intrinsics.fx * p.x() * inv_z + intrinsics.cx + 0.5f;
      const float v = intrinsics.fy * p.y() * inv_z + intrinsics.cy + 0.5f;
      if (u >= 0.f && v >= 0.f && u < width && v < height) {
        key = static_cast<int>(v) * width + static_cast<int>(u);
      }
    }
    keys_[i] = key;
    ++bucket_start_[static_cast<size_t>(key) + 1];
  }
  for (size_t b = 1; b < bucket_start_.size(); ++b) bucket_start_[b] += bucket_start_[b - 1];

  // Same capacity as the model: the frames after a sort append without reallocating it.
  sorted_.reserve(surfels.capacity());
  sorted_.resize(surfels.size());
  for (size_t i = 0; i < surfels.size(); ++i) {
    sorted_[static_cast<size_t>(bucket_start_[static_cast<size_t>(keys_[i])]++)] = surfels[i];
  }
  surfels.swap(sorted_);
}

}  // namespace vicc_fusion
