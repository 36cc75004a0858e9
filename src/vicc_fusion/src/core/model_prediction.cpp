#include "vicc_fusion/model_prediction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "vicc_tracking/simd4.hpp"

namespace vicc_fusion {

void ModelPredictionConfig::validate() const {
  if (!(stable_confidence > 0.0)) {
    throw std::invalid_argument("model prediction: stable_confidence must be > 0");
  }
  if (!(splat_radius_scale >= 1.0)) {
    throw std::invalid_argument("model prediction: splat_radius_scale must be >= 1");
  }
  if (!(blend_depth >= 0.0))
    throw std::invalid_argument("model prediction: blend_depth must be >= 0");
  if (!(max_splat_radius_px >= 0.5)) {
    throw std::invalid_argument("model prediction: max_splat_radius_px must be >= 0.5");
  }
  if (!(min_depth > 0.0)) throw std::invalid_argument("model prediction: min_depth must be > 0");
}

namespace {

using vicc_tracking::simd::Float4;
using vicc_tracking::simd::load4;
using vicc_tracking::simd::Mask4;
using vicc_tracking::simd::store4;

/// Per pixel, the discs covering it: the front one and those within the blend depth behind
/// it. All lie on the pixel's ray, so their (inverse) depth is all it takes to place the
/// vertex; inverse depth is affine across a disc, which spares a division per pixel.
/// One plane per sum (front inverse depth, weight, weighted inverse depth, weighted normal),
/// with a border of one pixel left, top and bottom and three right: four-pixel row segments
/// starting anywhere in -1..width stay inside.
class SplatPlanes {
 public:
  enum Plane { kFront, kWeight, kInvDepthSum, kNormalX, kNormalY, kNormalZ, kPlaneCount };

  SplatPlanes(int width, int height)
      : stride_(static_cast<size_t>(width) + 4),
        plane_size_(stride_ * (static_cast<size_t>(height) + 2)),
        data_(kPlaneCount * plane_size_, 0.f) {}

  const float* at(Plane plane, int u, int v) const {
    return &data_[plane * plane_size_ + static_cast<size_t>(v + 1) * stride_ + (u + 1)];
  }

  /// Adds a disc to the pixels (u..u+3, v); lanes with w == 0 stay untouched. Selects instead
  /// of branches: whether a disc hides, joins or misses the front is data-dependent.
  void add(int u, int v, Float4 inv_depth, Float4 w, const Eigen::Vector3f& normal, float blend) {
    float* front_ptr = &data_[static_cast<size_t>(v + 1) * stride_ + (u + 1)];
    float* weight_ptr = front_ptr + plane_size_;
    float* inv_depth_ptr = weight_ptr + plane_size_;
    float* nx_ptr = inv_depth_ptr + plane_size_;
    float* ny_ptr = nx_ptr + plane_size_;
    float* nz_ptr = ny_ptr + plane_size_;
    const Float4 front = load4(front_ptr);
    const Mask4 covers = w > 0.f;
    const Mask4 hides = covers & (inv_depth > front + blend);   // a new front surface
    const Mask4 joins = covers & (inv_depth >= front - blend);  // within the blend (or hides)
    const Float4 zero = {0.f, 0.f, 0.f, 0.f}, one = {1.f, 1.f, 1.f, 1.f};
    const Float4 keep = hides ? zero : one;
    const Float4 take = joins ? w : zero;
    store4(front_ptr, joins & (inv_depth > front) ? inv_depth : front);
    store4(weight_ptr, load4(weight_ptr) * keep + take);
    store4(inv_depth_ptr, load4(inv_depth_ptr) * keep + take * inv_depth);
    store4(nx_ptr, load4(nx_ptr) * keep + take * normal.x());
    store4(ny_ptr, load4(ny_ptr) * keep + take * normal.y());
    store4(nz_ptr, load4(nz_ptr) * keep + take * normal.z());
  }

 private:
  size_t stride_, plane_size_;
  std::vector<float> data_;
};

// std::floor and std::ceil are library calls on baseline x86-64 (no SSE4.1 rounding); these
// run twice per splatted row. Arguments stay within a few pixels of the image.
int floorToInt(float x) {
  const int truncated = static_cast<int>(x);
  return truncated > x ? truncated - 1 : truncated;
}
int ceilToInt(float x) {
  const int truncated = static_cast<int>(x);
  return truncated < x ? truncated + 1 : truncated;
}

}  // namespace

vicc_tracking::DepthLevel renderModel(const SurfelVector& surfels,
                                      const Eigen::Isometry3d& camera_pose,
                                      const vicc_tracking::PinholeIntrinsics& intrinsics,
                                      const ModelPredictionConfig& config) {
  const int width = intrinsics.width, height = intrinsics.height;
  const size_t count = static_cast<size_t>(width) * height;
  SplatPlanes planes(width, height);
  const Float4 lane = {0.f, 1.f, 2.f, 3.f};

  const Eigen::Isometry3f map_to_camera = camera_pose.cast<float>().inverse();
  const Eigen::Matrix3f rotation = map_to_camera.linear();
  const Eigen::Vector3f translation = map_to_camera.translation();
  const float inv_fx = 1.f / intrinsics.fx, inv_fy = 1.f / intrinsics.fy;
  const float stable = static_cast<float>(config.stable_confidence);
  const float blend = static_cast<float>(config.blend_depth);
  const float radius_scale = static_cast<float>(config.splat_radius_scale);
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
    // Most of the model lies outside the view: leave before the footprint's square roots.
    if (u0 < -max_splat || v0 < -max_splat || u0 > width + max_splat || v0 > height + max_splat) {
      continue;
    }
    // Screen footprint of the disc, first order at its centre: the ellipse spanned by two
    // orthogonal radius vectors through the projection's Jacobian J. A disc seen at a grazing
    // angle is a thin ellipse, so its bounding box stays small.
    const float radius = surfel.radius * radius_scale;
    Eigen::Vector3f axis_a;
    if (std::abs(normal.x()) < 0.9f) {  // normal x (1, 0, 0), normalised
      const float inv = 1.f / std::sqrt(normal.y() * normal.y() + normal.z() * normal.z());
      axis_a = Eigen::Vector3f(0.f, normal.z() * inv, -normal.y() * inv);
    } else {  // normal x (0, 1, 0), normalised
      const float inv = 1.f / std::sqrt(normal.x() * normal.x() + normal.z() * normal.z());
      axis_a = Eigen::Vector3f(-normal.z() * inv, 0.f, normal.x() * inv);
    }
    const Eigen::Vector3f axis_b(normal.y() * axis_a.z() - normal.z() * axis_a.y(),
                                 normal.z() * axis_a.x() - normal.x() * axis_a.z(),
                                 normal.x() * axis_a.y() - normal.y() * axis_a.x());
    const float ju_x = radius * intrinsics.fx * inv_z;
    const float ju_z = -ju_x * center.x() * inv_z;
    const float jv_y = radius * intrinsics.fy * inv_z;
    const float jv_z = -jv_y * center.y() * inv_z;
    const float ax = ju_x * axis_a.x() + ju_z * axis_a.z();
    const float bx = ju_x * axis_b.x() + ju_z * axis_b.z();
    const float ay = jv_y * axis_a.y() + jv_z * axis_a.z();
    const float by = jv_y * axis_b.y() + jv_z * axis_b.z();
    const float determinant = ax * by - bx * ay;
    if (std::abs(determinant) < 1e-6f) continue;  // seen edge-on: covers no pixel
    const float extent_u = std::min(max_splat, std::sqrt(ax * ax + bx * bx));
    const float extent_v = std::min(max_splat, std::sqrt(ay * ay + by * by));
    // Truncation is floor here: negative bounds are clamped to 0 anyway.
    const int u_min = std::max(0, static_cast<int>(u0 - extent_u + 0.5f));
    const int u_max = std::min(width - 1, static_cast<int>(u0 + extent_u + 0.5f));
    const int v_min = std::max(0, static_cast<int>(v0 - extent_v + 0.5f));
    const int v_max = std::min(height - 1, static_cast<int>(v0 + extent_v + 0.5f));
    // Per pixel: (s, t) = [A B]^-1 (du, dv) are the pixel centre's disc coordinates (inside
    // when s^2 + t^2 <= 1); 1/depth is affine in (u, v) on the plane: 1/z = n.ray(u, v) / n.c.
    // Along a row, s and t are affine in du, so r^2 = s^2 + t^2 is a quadratic whose roots
    // bound the covered pixels: only those are visited (most of the box lies outside).
    const float inv_det = 1.f / determinant;
    const float s_du = by * inv_det, t_du = -ay * inv_det;
    const float r2_a = s_du * s_du + t_du * t_du;  // > 0: the footprint is not degenerate
    const float inv_2a = 0.5f / r2_a;
    const float inv_facing = 1.f / facing;
    const float depth_du = normal.x() * inv_fx * inv_facing;
    const float depth_dv = normal.y() * inv_fy * inv_facing;
    const float depth_0 =
        (normal.z() - normal.x() * intrinsics.cx * inv_fx - normal.y() * intrinsics.cy * inv_fy) *
        inv_facing;
    const float blend_inverse = blend * inv_z * inv_z;  // d(1/z) = dz / z^2
    const float confidence = surfel.confidence;
    // Pixels u..u+3 of row v; lanes past `last` or outside the disc get no weight.
    const auto splat = [&](int u, int v, int last) {
      const float dv = v - v0;
      const Float4 du = (static_cast<float>(u) - u0) + lane;
      const Float4 s = (-bx * dv * inv_det) + s_du * du;
      const Float4 t = (ax * dv * inv_det) + t_du * du;
      const Float4 r2 = s * s + t * t;
      const Float4 inv_depth = (depth_0 + depth_dv * v) + depth_du * (static_cast<float>(u) + lane);
      const Float4 zero = {0.f, 0.f, 0.f, 0.f};
      const Float4 w = (r2 <= 1.f) & (inv_depth > 0.f) & (lane <= static_cast<float>(last - u))
                           ? confidence * (1.1f - r2)
                           : zero;
      planes.add(u, v, inv_depth, w, normal, blend_inverse);
    };
    const int center_u = floorToInt(u0 + 0.5f), center_v = floorToInt(v0 + 0.5f);
    if (extent_u < 1.5f && extent_v < 1.5f && center_u >= 0 && center_u < width && center_v >= 0 &&
        center_v < height) {
      // Most footprints are under 1.5 px: all pixel centres they cover lie in the 3x3 block
      // around the centre's pixel. Three four-wide rows, no per-pixel branches.
      for (int v = center_v - 1; v <= center_v + 1; ++v) splat(center_u - 1, v, center_u + 1);
      continue;
    }
    // Larger footprints: along a row, s and t are affine in du, so r^2 = s^2 + t^2 is a
    // quadratic whose roots bound the covered pixels.
    for (int v = v_min; v <= v_max; ++v) {
      const float dv = v - v0;
      const float s_0 = -bx * dv * inv_det, t_0 = ax * dv * inv_det;
      const float r2_b = 2.f * (s_0 * s_du + t_0 * t_du);
      const float r2_c = s_0 * s_0 + t_0 * t_0;
      const float discriminant = r2_b * r2_b - 4.f * r2_a * (r2_c - 1.f);
      if (discriminant < 0.f) continue;  // the row misses the ellipse
      const float root = std::sqrt(discriminant);
      const int first = std::max(u_min, ceilToInt(u0 + (-r2_b - root) * inv_2a));
      const int last = std::min(u_max, floorToInt(u0 + (-r2_b + root) * inv_2a));
      for (int u = first; u <= last; u += 4) splat(u, v, last);
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
  for (int v = 0; v < height; ++v) {
    const float* weight_row = planes.at(SplatPlanes::kWeight, 0, v);
    const float* inv_depth_row = planes.at(SplatPlanes::kInvDepthSum, 0, v);
    const float* nx_row = planes.at(SplatPlanes::kNormalX, 0, v);
    const float* ny_row = planes.at(SplatPlanes::kNormalY, 0, v);
    const float* nz_row = planes.at(SplatPlanes::kNormalZ, 0, v);
    for (int u = 0; u < width; ++u) {
      if (weight_row[u] <= 0.f) continue;
      const Eigen::Vector3f normal_sum(nx_row[u], ny_row[u], nz_row[u]);
      const float normal_length = normal_sum.norm();
      if (normal_length <= 0.f) continue;
      const float z = weight_row[u] / inv_depth_row[u];
      const Eigen::Vector3f point((u - intrinsics.cx) * inv_fx * z,
                                  (v - intrinsics.cy) * inv_fy * z, z);
      const Eigen::Vector3f normal = normal_sum / normal_length;
      const size_t i = static_cast<size_t>(v) * width + u;
      level.vertices[i] = point;
      level.normals[i] = normal;
      depth[i] = point.z();
      const float cos_view = std::max(0.26f, std::abs(normal.dot(point.normalized())));
      level.radii[i] = std::sqrt(2.f) * 0.5f * point.z() / mean_focal / cos_view;
      ++level.valid_vertices;
      ++level.valid_normals;
    }
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
