#include "vicc_fusion/model_prediction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace vicc_fusion {

void ModelPredictionConfig::validate() const {
  if (!(stable_confidence > 0.0)) {
    throw std::invalid_argument("model prediction: stable_confidence must be > 0");
  }
  if (!(blend_depth >= 0.0))
    throw std::invalid_argument("model prediction: blend_depth must be >= 0");
  if (!(max_splat_radius_px >= 0.5)) {
    throw std::invalid_argument("model prediction: max_splat_radius_px must be >= 0.5");
  }
  if (!(min_depth > 0.0)) throw std::invalid_argument("model prediction: min_depth must be > 0");
}

namespace {

/// The discs covering one pixel: the front one and those within the blend depth behind it.
struct SplatPixel {
  float front = std::numeric_limits<float>::infinity();
  float weight = 0.f;
  Eigen::Vector3f position_sum = Eigen::Vector3f::Zero();
  Eigen::Vector3f normal_sum = Eigen::Vector3f::Zero();

  void add(float depth, float w, const Eigen::Vector3f& point, const Eigen::Vector3f& normal,
           float blend) {
    if (depth < front - blend) {  // a new front surface hides what was there
      front = depth;
      weight = w;
      position_sum = w * point;
      normal_sum = w * normal;
    } else if (depth <= front + blend) {
      front = std::min(front, depth);
      weight += w;
      position_sum += w * point;
      normal_sum += w * normal;
    }
  }
};

}  // namespace

vicc_tracking::DepthLevel renderModel(const SurfelVector& surfels,
                                      const Eigen::Isometry3d& camera_pose,
                                      const vicc_tracking::PinholeIntrinsics& intrinsics,
                                      const ModelPredictionConfig& config) {
  const int width = intrinsics.width, height = intrinsics.height;
  const size_t count = static_cast<size_t>(width) * height;
  std::vector<SplatPixel> buffer(count);  // one array: a pixel's sums share a cache line

  const Eigen::Isometry3f map_to_camera = camera_pose.cast<float>().inverse();
  const Eigen::Matrix3f rotation = map_to_camera.linear();
  const Eigen::Vector3f translation = map_to_camera.translation();
  const float inv_fx = 1.f / intrinsics.fx, inv_fy = 1.f / intrinsics.fy;
  const float stable = static_cast<float>(config.stable_confidence);
  const float blend = static_cast<float>(config.blend_depth);
  const float max_splat = static_cast<float>(config.max_splat_radius_px);
  const float min_depth = static_cast<float>(config.min_depth);

  for (const Surfel& surfel : surfels) {
    if (surfel.confidence < stable) continue;
    const Eigen::Vector3f center = rotation * surfel.position + translation;
    if (center.z() < min_depth) continue;
    const Eigen::Vector3f normal = rotation * surfel.normal;
    const float facing = normal.dot(center);
    if (facing >= 0.f) continue;  // back side: the camera cannot see this disc
    const float inv_z = 1.f / center.z();
    const float u0 = intrinsics.fx * center.x() * inv_z + intrinsics.cx;
    const float v0 = intrinsics.fy * center.y() * inv_z + intrinsics.cy;
    // Screen footprint of the disc: the ellipse spanned by two orthogonal radius vectors
    // through the projection's Jacobian at the centre. A disc seen at a grazing angle is a
    // thin ellipse, so a circle of its full radius would test many pixels for nothing.
    const Eigen::Vector3f axis_a = normal.unitOrthogonal();
    const Eigen::Vector3f axis_b(normal.y() * axis_a.z() - normal.z() * axis_a.y(),
                                 normal.z() * axis_a.x() - normal.x() * axis_a.z(),
                                 normal.x() * axis_a.y() - normal.y() * axis_a.x());
    const float scale = surfel.radius * inv_z;
    const float ax = intrinsics.fx * scale * (axis_a.x() - center.x() * inv_z * axis_a.z());
    const float bx = intrinsics.fx * scale * (axis_b.x() - center.x() * inv_z * axis_b.z());
    const float ay = intrinsics.fy * scale * (axis_a.y() - center.y() * inv_z * axis_a.z());
    const float by = intrinsics.fy * scale * (axis_b.y() - center.y() * inv_z * axis_b.z());
    const float extent_u = std::min(max_splat, std::sqrt(ax * ax + bx * bx));
    const float extent_v = std::min(max_splat, std::sqrt(ay * ay + by * by));
    const int u_min = std::max(0, static_cast<int>(std::floor(u0 - extent_u + 0.5f)));
    const int u_max = std::min(width - 1, static_cast<int>(std::floor(u0 + extent_u + 0.5f)));
    const int v_min = std::max(0, static_cast<int>(std::floor(v0 - extent_v + 0.5f)));
    const int v_max = std::min(height - 1, static_cast<int>(std::floor(v0 + extent_v + 0.5f)));
    const float radius_squared = surfel.radius * surfel.radius;
    for (int v = v_min; v <= v_max; ++v) {
      for (int u = u_min; u <= u_max; ++u) {
        // The pixel's ray (x, y, 1) meets the disc's plane where n.(t ray - c) = 0.
        const Eigen::Vector3f ray((u - intrinsics.cx) * inv_fx, (v - intrinsics.cy) * inv_fy, 1.f);
        const float along = normal.dot(ray);
        if (along >= 0.f) continue;
        const float t = facing / along;
        const Eigen::Vector3f point = t * ray;
        if ((point - center).squaredNorm() > radius_squared) continue;
        const float falloff = 1.f - (point - center).squaredNorm() / radius_squared;
        buffer[static_cast<size_t>(v) * width + u].add(t, surfel.confidence * (0.1f + falloff),
                                                       point, normal, blend);
      }
    }
  }

  vicc_tracking::DepthLevel level;
  level.intrinsics = intrinsics;
  level.depth = cv::Mat1f(height, width, 0.f);
  level.vertices.assign(count, Eigen::Vector3f::Zero());
  level.normals.assign(count, Eigen::Vector3f::Zero());
  level.radii.assign(count, 0.f);
  float* depth = level.depth.ptr<float>(0);
  const float mean_focal = 0.5f * (intrinsics.fx + intrinsics.fy);
  for (size_t i = 0; i < count; ++i) {
    const SplatPixel& pixel = buffer[i];
    if (pixel.weight <= 0.f) continue;
    const Eigen::Vector3f point = pixel.position_sum / pixel.weight;
    const float normal_length = pixel.normal_sum.norm();
    if (normal_length <= 0.f) continue;
    const Eigen::Vector3f normal = pixel.normal_sum / normal_length;
    level.vertices[i] = point;
    level.normals[i] = normal;
    depth[i] = point.z();
    const float cos_view = std::max(0.26f, std::abs(normal.dot(point.normalized())));
    level.radii[i] = std::sqrt(2.f) * 0.5f * point.z() / mean_focal / cos_view;
    ++level.valid_vertices;
    ++level.valid_normals;
  }
  return level;
}

vicc_tracking::DepthPyramid predictPyramid(const SurfelVector& surfels,
                                           const Eigen::Isometry3d& camera_pose,
                                           const vicc_tracking::DepthPyramid& frame,
                                           const vicc_tracking::PreprocessingConfig& preprocessing,
                                           const ModelPredictionConfig& config) {
  if (frame.empty()) throw std::invalid_argument("model prediction: empty frame pyramid");
  vicc_tracking::DepthPyramid pyramid;
  pyramid.reserve(frame.size());
  pyramid.push_back(renderModel(surfels, camera_pose, frame.front().intrinsics, config));
  for (size_t level = 1; level < frame.size(); ++level) {
    const cv::Mat1f depth = vicc_tracking::downsampleDepth(
        pyramid.back().depth, static_cast<float>(preprocessing.pyramid_depth_threshold));
    pyramid.push_back(vicc_tracking::computeDepthLevel(depth, frame[level].intrinsics,
                                                       preprocessing.normal_depth_jump * 2.0));
  }
  return pyramid;
}

}  // namespace vicc_fusion
