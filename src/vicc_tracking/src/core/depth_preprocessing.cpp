#include "vicc_tracking/depth_preprocessing.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

namespace vicc_tracking {

void PreprocessingConfig::validate() const {
  if (pyramid_levels < 1 || pyramid_levels > 3) {
    throw std::invalid_argument("pyramid_levels must be 1, 2 or 3, got " +
                                std::to_string(pyramid_levels));
  }
  if (!(min_depth >= 0.0) || !(max_depth > min_depth)) {
    throw std::invalid_argument("depth range needs 0 <= min_depth < max_depth");
  }
  if (bilateral_filter && (bilateral_diameter < 1 || !(bilateral_sigma_depth > 0.0) ||
                           !(bilateral_sigma_space > 0.0))) {
    throw std::invalid_argument("bilateral filter needs diameter >= 1 and positive sigmas");
  }
  if (!(pyramid_depth_threshold > 0.0) || !(normal_depth_jump > 0.0)) {
    throw std::invalid_argument("pyramid_depth_threshold and normal_depth_jump must be > 0");
  }
}

cv::Mat1f toMetricDepth(const cv::Mat& raw) {
  cv::Mat1f metric;
  if (raw.type() == CV_32FC1) {
    metric = raw.clone();
  } else if (raw.type() == CV_16UC1) {
    raw.convertTo(metric, CV_32F, 0.001);
  } else {
    throw std::invalid_argument(
        "unsupported depth image type (expected 32FC1 metres or 16UC1 "
        "millimetres)");
  }
  for (int v = 0; v < metric.rows; ++v) {
    float* row = metric.ptr<float>(v);
    for (int u = 0; u < metric.cols; ++u) {
      if (!std::isfinite(row[u]) || row[u] < 0.f) row[u] = 0.f;
    }
  }
  return metric;
}

PinholeIntrinsics PinholeIntrinsics::halved() const {
  PinholeIntrinsics half;
  half.width = width / 2;
  half.height = height / 2;
  half.fx = fx * 0.5f;
  half.fy = fy * 0.5f;
  // Pixel centres sit at integer coordinates: a 2x2 block's centre maps to (2u + 0.5).
  half.cx = (cx - 0.5f) * 0.5f;
  half.cy = (cy - 0.5f) * 0.5f;
  return half;
}

namespace {

/// Empty maps of `count` pixels for a level.
DepthLevel emptyLevel(const PinholeIntrinsics& intrinsics, size_t count) {
  DepthLevel level;
  level.intrinsics = intrinsics;
  level.vertices.assign(count, Eigen::Vector3f::Zero());
  level.normals.assign(count, Eigen::Vector3f::Zero());
  level.radii.assign(count, 0.f);
  return level;
}

/// Normal and splat radius at `center` from its four neighbours (central differences);
/// false at depth edges and holes, where a normal would be meaningless.
struct NormalEstimator {
  float max_jump;
  float radius_factor;  ///< sqrt(2) / 2 / mean focal length

  bool operator()(const Eigen::Vector3f& center, const Eigen::Vector3f& left,
                  const Eigen::Vector3f& right, const Eigen::Vector3f& up,
                  const Eigen::Vector3f& down, Eigen::Vector3f& normal, float& radius) const {
    if (left.z() <= 0.f || right.z() <= 0.f || up.z() <= 0.f || down.z() <= 0.f) return false;
    if (std::abs(right.z() - left.z()) > max_jump || std::abs(down.z() - up.z()) > max_jump) {
      return false;
    }
    // Cross product written out: Eigen's SSE cross() trips a false GCC 12 array-bounds error.
    const Eigen::Vector3f a = right - left;
    const Eigen::Vector3f b = down - up;
    normal = Eigen::Vector3f(a.y() * b.z() - a.z() * b.y(), a.z() * b.x() - a.x() * b.z(),
                             a.x() * b.y() - a.y() * b.x());
    const float length = normal.norm();
    if (length <= 0.f) return false;
    normal /= length;
    if (normal.dot(center) > 0.f) normal = -normal;  // face the camera
    // Splat radius as in Keller et al.: grows with distance and with grazing view angles.
    const float cos_view = std::max(0.26f, std::abs(normal.dot(center)) / center.norm());
    radius = radius_factor * center.z() / cos_view;
    return true;
  }
};

NormalEstimator normalEstimator(const PinholeIntrinsics& intrinsics, double normal_depth_jump) {
  return {static_cast<float>(normal_depth_jump),
          std::sqrt(2.f) * 0.5f / (0.5f * (intrinsics.fx + intrinsics.fy))};
}

}  // namespace

DepthLevel computeDepthLevel(const cv::Mat1f& depth, const PinholeIntrinsics& intrinsics,
                             double normal_depth_jump, const std::vector<Eigen::Vector2f>* rays) {
  const int width = depth.cols;
  const int height = depth.rows;
  DepthLevel level = emptyLevel(intrinsics, static_cast<size_t>(width) * height);
  level.depth = depth;

  const float inv_fx = 1.f / intrinsics.fx;
  const float inv_fy = 1.f / intrinsics.fy;
  for (int v = 0; v < height; ++v) {
    const float* row = depth.ptr<float>(v);
    for (int u = 0; u < width; ++u) {
      const float z = row[u];
      if (z <= 0.f) continue;
      // Eq. 2.4: V(u) = D(u) K^-1 (u, 1), with the sensor's exact ray when known.
      const int index = v * width + u;
      if (rays) {
        const Eigen::Vector2f& ray = (*rays)[index];
        level.vertices[index] = Eigen::Vector3f(ray.x() * z, ray.y() * z, z);
      } else {
        level.vertices[index] =
            Eigen::Vector3f((u - intrinsics.cx) * z * inv_fx, (v - intrinsics.cy) * z * inv_fy, z);
      }
      ++level.valid_vertices;
    }
  }

  const NormalEstimator estimate = normalEstimator(intrinsics, normal_depth_jump);
  for (int v = 1; v + 1 < height; ++v) {
    for (int u = 1; u + 1 < width; ++u) {
      const int index = v * width + u;
      const Eigen::Vector3f& center = level.vertices[index];
      if (center.z() <= 0.f) continue;
      if (estimate(center, level.vertices[index - 1], level.vertices[index + 1],
                   level.vertices[index - width], level.vertices[index + width],
                   level.normals[index], level.radii[index])) {
        ++level.valid_normals;
      }
    }
  }
  return level;
}

namespace {

/// A level on the pinhole grid computed straight from the distorted sensor depth: each pixel
/// takes the vertex, normal and radius of its nearest sensor pixel (`source_index`), with the
/// normal from that pixel's sensor neighbours. Same result as computing the level on the
/// sensor grid and resampling it, without the intermediate maps.
DepthLevel computeUndistortedLevel(const cv::Mat1f& sensor_depth,
                                   const PinholeIntrinsics& intrinsics, double normal_depth_jump,
                                   const std::vector<Eigen::Vector2f>& rays,
                                   const std::vector<int>& source_index) {
  const int width = sensor_depth.cols, height = sensor_depth.rows;
  DepthLevel level = emptyLevel(intrinsics, source_index.size());
  level.depth = cv::Mat1f(intrinsics.height, intrinsics.width, 0.f);
  const float* depth = sensor_depth.ptr<float>(0);
  const auto vertex_at = [&](int s) {
    const float z = depth[s];
    return z > 0.f ? Eigen::Vector3f(rays[s].x() * z, rays[s].y() * z, z)
                   : Eigen::Vector3f::Zero().eval();
  };
  const NormalEstimator estimate = normalEstimator(intrinsics, normal_depth_jump);
  float* out_depth = level.depth.ptr<float>(0);
  for (size_t i = 0; i < source_index.size(); ++i) {
    const int s = source_index[i];
    if (s < 0 || depth[s] <= 0.f) continue;
    const Eigen::Vector3f center = vertex_at(s);
    level.vertices[i] = center;
    out_depth[i] = center.z();
    ++level.valid_vertices;
    const int su = s % width, sv = s / width;
    if (su < 1 || sv < 1 || su + 1 >= width || sv + 1 >= height) continue;
    if (estimate(center, vertex_at(s - 1), vertex_at(s + 1), vertex_at(s - width),
                 vertex_at(s + width), level.normals[i], level.radii[i])) {
      ++level.valid_normals;
    }
  }
  return level;
}

}  // namespace

cv::Mat1f downsampleDepth(const cv::Mat1f& depth, float threshold) {
  cv::Mat1f half(depth.rows / 2, depth.cols / 2, 0.f);
  for (int v = 0; v < half.rows; ++v) {
    const float* row0 = depth.ptr<float>(2 * v);
    const float* row1 = depth.ptr<float>(2 * v + 1);
    float* out = half.ptr<float>(v);
    for (int u = 0; u < half.cols; ++u) {
      const float block[4] = {row0[2 * u], row0[2 * u + 1], row1[2 * u], row1[2 * u + 1]};
      float nearest = 0.f;
      for (float d : block) {
        if (d > 0.f && (nearest == 0.f || d < nearest)) nearest = d;
      }
      if (nearest == 0.f) continue;
      float sum = 0.f;
      int n = 0;
      for (float d : block) {
        if (d > 0.f && d - nearest <= threshold) {
          sum += d;
          ++n;
        }
      }
      out[u] = sum / n;
    }
  }
  return half;
}

DepthPreprocessor::DepthPreprocessor(const PreprocessingConfig& config) : config_(config) {
  config_.validate();
}

void DepthPreprocessor::setCamera(const CameraModel& camera) {
  camera.validate();
  const bool same = has_camera_ && camera.width == camera_.width &&
                    camera.height == camera_.height && camera.fx == camera_.fx &&
                    camera.fy == camera_.fy && camera.cx == camera_.cx && camera.cy == camera_.cy &&
                    camera.model == camera_.model && camera.distortion == camera_.distortion;
  if (same) return;
  camera_ = camera;
  has_camera_ = true;
  undistort_map1_.release();
  undistort_map2_.release();
  levels_.clear();

  PinholeIntrinsics intrinsics;
  intrinsics.width = camera_.width;
  intrinsics.height = camera_.height;
  intrinsics.fx = static_cast<float>(camera_.fx);
  intrinsics.fy = static_cast<float>(camera_.fy);
  intrinsics.cx = static_cast<float>(camera_.cx);
  intrinsics.cy = static_cast<float>(camera_.cy);
  for (int level = 0; level < config_.pyramid_levels; ++level) {
    if (level > 0) intrinsics = intrinsics.halved();
    LevelGeometry geometry;
    geometry.intrinsics = intrinsics;
    if (camera_.hasDistortion()) {
      // The level's sensor: same distortion (it acts on normalised coordinates), scaled K.
      CameraModel scaled = camera_;
      scaled.width = intrinsics.width;
      scaled.height = intrinsics.height;
      scaled.fx = intrinsics.fx;
      scaled.fy = intrinsics.fy;
      scaled.cx = intrinsics.cx;
      scaled.cy = intrinsics.cy;
      for (const Eigen::Vector2d& ray : scaled.normalizedRaysForAllPixels()) {
        geometry.sensor_rays.push_back(ray.cast<float>());
      }
      cv::Mat map_x, map_y;
      const cv::Matx33d k = scaled.intrinsicMatrix();
      const cv::Size size(intrinsics.width, intrinsics.height);
      if (camera_.model == DistortionModel::kEquidistant) {
        cv::fisheye::initUndistortRectifyMap(k, camera_.distortionCoefficients(),
                                             cv::Matx33d::eye(), k, size, CV_32FC1, map_x, map_y);
      } else {
        cv::initUndistortRectifyMap(k, camera_.distortionCoefficients(), cv::Matx33d::eye(), k,
                                    size, CV_32FC1, map_x, map_y);
      }
      if (level == 0) {
        cv::convertMaps(map_x, map_y, undistort_map1_, undistort_map2_, CV_16SC2, true);
      }
      geometry.source_index.assign(static_cast<size_t>(size.area()), -1);
      for (int v = 0; v < size.height; ++v) {
        for (int u = 0; u < size.width; ++u) {
          const int su = static_cast<int>(std::lround(map_x.at<float>(v, u)));
          const int sv = static_cast<int>(std::lround(map_y.at<float>(v, u)));
          if (su < 0 || sv < 0 || su >= size.width || sv >= size.height) continue;
          geometry.source_index[static_cast<size_t>(v) * size.width + u] = sv * size.width + su;
        }
      }
    }
    levels_.push_back(std::move(geometry));
  }
}

cv::Mat1f DepthPreprocessor::undistort(const cv::Mat1f& metric_depth) const {
  if (undistort_map1_.empty()) return metric_depth;
  cv::Mat1f undistorted;
  cv::remap(metric_depth, undistorted, undistort_map1_, undistort_map2_, cv::INTER_NEAREST,
            cv::BORDER_CONSTANT, cv::Scalar(0.f));
  return undistorted;
}

DepthPyramid DepthPreprocessor::process(const cv::Mat& raw) const {
  if (!has_camera_) throw std::logic_error("DepthPreprocessor: no camera set");
  if (raw.cols != camera_.width || raw.rows != camera_.height) {
    throw std::invalid_argument("depth image is " + std::to_string(raw.cols) + "x" +
                                std::to_string(raw.rows) + " but camera_info says " +
                                std::to_string(camera_.width) + "x" +
                                std::to_string(camera_.height));
  }
  cv::Mat1f depth = toMetricDepth(raw);  // a new image: the caller's stays untouched
  const float min_depth = static_cast<float>(config_.min_depth);
  const float max_depth = static_cast<float>(config_.max_depth);
  for (int v = 0; v < depth.rows; ++v) {
    float* row = depth.ptr<float>(v);
    for (int u = 0; u < depth.cols; ++u) {
      if (row[u] < min_depth || row[u] > max_depth) row[u] = 0.f;
    }
  }

  if (config_.bilateral_filter) {
    cv::Mat1f filtered;
    cv::bilateralFilter(depth, filtered, config_.bilateral_diameter, config_.bilateral_sigma_depth,
                        config_.bilateral_sigma_space);
    // Invalid pixels stay invalid; valid ones never take a value blended with "0".
    for (int v = 0; v < depth.rows; ++v) {
      const float* input = depth.ptr<float>(v);
      float* output = filtered.ptr<float>(v);
      for (int u = 0; u < depth.cols; ++u) {
        if (input[u] == 0.f) output[u] = 0.f;
      }
    }
    depth = filtered;
  }

  DepthPyramid pyramid;
  pyramid.reserve(config_.pyramid_levels);
  for (int level = 0; level < config_.pyramid_levels; ++level) {
    if (level > 0) {
      depth = downsampleDepth(depth, static_cast<float>(config_.pyramid_depth_threshold));
    }
    const LevelGeometry& geometry = levels_[level];
    const double jump = config_.normal_depth_jump * (level > 0 ? 2.0 : 1.0);
    if (geometry.source_index.empty()) {
      pyramid.push_back(computeDepthLevel(depth, geometry.intrinsics, jump));
    } else {
      pyramid.push_back(computeUndistortedLevel(depth, geometry.intrinsics, jump,
                                                geometry.sensor_rays, geometry.source_index));
    }
  }
  return pyramid;
}

}  // namespace vicc_tracking
