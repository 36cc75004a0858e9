#include "vicc_tracking/depth_preprocessing.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "vicc_tracking/simd4.hpp"

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

using simd::Float4;
using simd::load4;
using simd::Mask4;
using simd::store4;

/// Vertex, normal and splat radius of every pixel of a depth grid, one plane per quantity
/// (row-major; a zero normal marks pixels without one). Planes let the normals be computed
/// four pixels at a time.
struct GridPlanes {
  int width = 0, height = 0;
  std::vector<float> x, y, z, nx, ny, nz, radius;
};

/// Eq. 2.4, V(u) = D(u) K^-1 (u, 1), with the sensor's exact ray per pixel when `rays` is
/// given; normals by central differences (none at holes and depth edges, where they would be
/// meaningless), facing the camera; splat radius as in Keller et al.: grows with distance and
/// with grazing view angles.
GridPlanes computeGridPlanes(const cv::Mat1f& depth, const PinholeIntrinsics& intrinsics,
                             double normal_depth_jump, const std::vector<Eigen::Vector2f>* rays) {
  GridPlanes planes;
  const int width = planes.width = depth.cols;
  const int height = planes.height = depth.rows;
  const size_t count = static_cast<size_t>(width) * height;
  // Zero padding: the last chunks of the bottom interior row read a few values past the end.
  planes.x.assign(count + 8, 0.f);
  planes.y.assign(count + 8, 0.f);
  planes.z.assign(count + 8, 0.f);
  const float inv_fx = 1.f / intrinsics.fx, inv_fy = 1.f / intrinsics.fy;
  for (int v = 0; v < height; ++v) {
    const float* row = depth.ptr<float>(v);
    for (int u = 0; u < width; ++u) {
      const size_t i = static_cast<size_t>(v) * width + u;
      const float z = row[u] > 0.f ? row[u] : 0.f;
      const float ray_x = rays ? (*rays)[i].x() : (u - intrinsics.cx) * inv_fx;
      const float ray_y = rays ? (*rays)[i].y() : (v - intrinsics.cy) * inv_fy;
      planes.x[i] = ray_x * z;
      planes.y[i] = ray_y * z;
      planes.z[i] = z;
    }
  }

  // Four pixels of a row at once; a chunk running past the row's last interior pixel writes
  // only zeros there, into border pixels or into pixels of the next row computed after it.
  for (auto* plane : {&planes.nx, &planes.ny, &planes.nz, &planes.radius}) {
    plane->assign(count + 4, 0.f);
  }
  const float max_jump = static_cast<float>(normal_depth_jump);
  const float radius_factor = std::sqrt(2.f) * 0.5f / (0.5f * (intrinsics.fx + intrinsics.fy));
  const Float4 zero = {0.f, 0.f, 0.f, 0.f};
  const float *x = planes.x.data(), *y = planes.y.data(), *z = planes.z.data();
  for (int v = 1; v + 1 < height; ++v) {
    for (int u = 1; u + 1 < width; u += 4) {
      const size_t i = static_cast<size_t>(v) * width + u;
      const size_t up = i - width, down = i + width;
      const Float4 cz = load4(z + i), lz = load4(z + i - 1), rz = load4(z + i + 1);
      const Float4 uz = load4(z + up), dz = load4(z + down);
      Mask4 valid = (cz > 0.f) & (lz > 0.f) & (rz > 0.f) & (uz > 0.f) & (dz > 0.f) &
                    (simd::abs4(rz - lz) <= max_jump) & (simd::abs4(dz - uz) <= max_jump);
      const Float4 ax = load4(x + i + 1) - load4(x + i - 1),
                   ay = load4(y + i + 1) - load4(y + i - 1);
      const Float4 az = rz - lz;
      const Float4 bx = load4(x + down) - load4(x + up), by = load4(y + down) - load4(y + up);
      const Float4 bz = dz - uz;
      Float4 nx = ay * bz - az * by, ny = az * bx - ax * bz, nz = ax * by - ay * bx;
      const Float4 length_sq = nx * nx + ny * ny + nz * nz;
      valid &= length_sq > 0.f;
      const Float4 inv_length = valid ? 1.f / simd::sqrt4(length_sq) : zero;
      const Float4 cx = load4(x + i), cy = load4(y + i);
      const Float4 facing = (nx * cx + ny * cy + nz * cz) * inv_length;
      const Float4 sign = facing > 0.f ? -inv_length : inv_length;  // face the camera
      nx *= sign;
      ny *= sign;
      nz *= sign;
      const Float4 center_length = simd::sqrt4(cx * cx + cy * cy + cz * cz);
      Float4 cos_view = valid ? simd::abs4(facing) / center_length : zero;
      cos_view = cos_view > 0.26f ? cos_view : Float4{0.26f, 0.26f, 0.26f, 0.26f};
      store4(&planes.nx[i], valid ? nx : zero);
      store4(&planes.ny[i], valid ? ny : zero);
      store4(&planes.nz[i], valid ? nz : zero);
      store4(&planes.radius[i], valid ? radius_factor * cz / cos_view : zero);
    }
  }
  return planes;
}

/// The level's maps from the planes: pixel i takes grid pixel source(i) (< 0: none).
template <typename Source>
DepthLevel levelFromPlanes(const GridPlanes& planes, const PinholeIntrinsics& intrinsics,
                           Source source) {
  DepthLevel level;
  level.intrinsics = intrinsics;
  const size_t count = static_cast<size_t>(intrinsics.width) * intrinsics.height;
  level.vertices.assign(count, Eigen::Vector3f::Zero());
  level.normals.assign(count, Eigen::Vector3f::Zero());
  level.radii.assign(count, 0.f);
  for (size_t i = 0; i < count; ++i) {
    const int s = source(i);
    if (s < 0 || planes.z[s] <= 0.f) continue;
    level.vertices[i] = Eigen::Vector3f(planes.x[s], planes.y[s], planes.z[s]);
    ++level.valid_vertices;
    if (planes.nz[s] == 0.f && planes.nx[s] == 0.f) continue;
    level.normals[i] = Eigen::Vector3f(planes.nx[s], planes.ny[s], planes.nz[s]);
    level.radii[i] = planes.radius[s];
    ++level.valid_normals;
  }
  return level;
}

}  // namespace

DepthLevel computeDepthLevel(const cv::Mat1f& depth, const PinholeIntrinsics& intrinsics,
                             double normal_depth_jump, const std::vector<Eigen::Vector2f>* rays) {
  const GridPlanes planes = computeGridPlanes(depth, intrinsics, normal_depth_jump, rays);
  DepthLevel level =
      levelFromPlanes(planes, intrinsics, [](size_t i) { return static_cast<int>(i); });
  level.depth = depth;
  return level;
}

namespace {

/// A level on the pinhole grid from the distorted sensor depth: each pixel takes the vertex,
/// normal and radius of its nearest sensor pixel (`source_index`), the normal computed from
/// that pixel's sensor neighbours.
DepthLevel computeUndistortedLevel(const cv::Mat1f& sensor_depth,
                                   const PinholeIntrinsics& intrinsics, double normal_depth_jump,
                                   const std::vector<Eigen::Vector2f>& rays,
                                   const std::vector<int>& source_index) {
  const GridPlanes planes = computeGridPlanes(sensor_depth, intrinsics, normal_depth_jump, &rays);
  DepthLevel level = levelFromPlanes(planes, intrinsics, [&](size_t i) { return source_index[i]; });
  level.depth = cv::Mat1f(intrinsics.height, intrinsics.width, 0.f);
  float* depth = level.depth.ptr<float>(0);
  for (size_t i = 0; i < level.vertices.size(); ++i) depth[i] = level.vertices[i].z();
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
  if (has_camera_ && camera == camera_) return;
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

void DepthPreprocessor::requireCameraSize(const cv::Mat& image, const char* what) const {
  if (!has_camera_) throw std::logic_error("DepthPreprocessor: no camera set");
  if (image.cols != camera_.width || image.rows != camera_.height) {
    throw std::invalid_argument(std::string(what) + " image is " + std::to_string(image.cols) +
                                "x" + std::to_string(image.rows) + " but camera_info says " +
                                std::to_string(camera_.width) + "x" +
                                std::to_string(camera_.height));
  }
}

cv::Mat1f DepthPreprocessor::undistortIntensity(const cv::Mat& sensor_image) const {
  requireCameraSize(sensor_image, "intensity");
  cv::Mat1f sensor;
  if (sensor_image.type() == CV_8UC1) {
    sensor_image.convertTo(sensor, CV_32F, 1.0 / 255.0);
  } else if (sensor_image.type() == CV_16UC1) {
    sensor_image.convertTo(sensor, CV_32F, 1.0 / 65535.0);
  } else if (sensor_image.type() == CV_32FC1) {
    sensor = sensor_image.clone();
  } else {
    throw std::invalid_argument(
        "unsupported intensity image type (expected mono8, mono16 or 32FC1)");
  }
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int v = 0; v < sensor.rows; ++v) {
    float* row = sensor.ptr<float>(v);
    for (int u = 0; u < sensor.cols; ++u) {
      if (!std::isfinite(row[u])) row[u] = nan;
    }
  }
  const std::vector<int>& source_index = levels_.front().source_index;
  if (source_index.empty()) return sensor;  // no distortion: the grids coincide
  cv::Mat1f undistorted(sensor.rows, sensor.cols, nan);
  const float* in = sensor.ptr<float>(0);  // continuous: a fresh conversion or clone
  float* out = undistorted.ptr<float>(0);
  for (size_t i = 0; i < source_index.size(); ++i) {
    if (source_index[i] >= 0) out[i] = in[source_index[i]];
  }
  return undistorted;
}

DepthPyramid DepthPreprocessor::process(const cv::Mat& raw) const {
  requireCameraSize(raw, "depth");
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
