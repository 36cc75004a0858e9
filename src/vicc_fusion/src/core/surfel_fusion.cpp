#include "vicc_fusion/surfel_fusion.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "vicc_tracking/simd4.hpp"

namespace vicc_fusion {
namespace {

void require(bool condition, const std::string& message) {
  if (!condition) throw std::invalid_argument("surfel fusion: " + message);
}

}  // namespace

void SurfelFusionConfig::validate() const {
  require(supersampling >= 1 && supersampling <= 8, "supersampling must be in 1..8");
  require(max_depth_difference > 0.0, "max_depth_difference must be > 0");
  require(max_normal_angle_deg > 0.0 && max_normal_angle_deg <= 90.0,
          "max_normal_angle_deg must be in (0, 90]");
  require(max_radius_growth >= 0.0, "max_radius_growth must be >= 0");
  require(confidence_sigma > 0.0, "confidence_sigma must be > 0");
  require(stable_confidence > 0.0, "stable_confidence must be > 0");
  require(unstable_lifetime >= 1, "unstable_lifetime must be >= 1 frame");
  require(free_space_margin > 0.0, "free_space_margin must be > 0");
  require(max_view_distance > 0.0, "max_view_distance must be > 0");
  require(max_surfels >= 1, "max_surfels must be >= 1");
  require(sort_interval >= 0, "sort_interval must be >= 0 (0 = never)");
}

SurfelFusion::SurfelFusion(const SurfelFusionConfig& config) { setConfig(config); }

void SurfelFusion::setConfig(const SurfelFusionConfig& config) {
  config.validate();
  config_ = config;
  min_normal_cosine_ = static_cast<float>(std::cos(config.max_normal_angle_deg * M_PI / 180.0));
  weights_width_ = weights_height_ = 0;  // the cached weights depend on confidence_sigma
}

void SurfelFusion::reset() {
  surfels_.clear();
  frame_index_ = 0;
  capacity_reached_ = false;
}

size_t SurfelFusion::stableCount() const {
  return static_cast<size_t>(std::count_if(surfels_.begin(), surfels_.end(),
                                           [this](const Surfel& s) { return isStable(s); }));
}

SurfelVector SurfelFusion::stableSurfels() const {
  SurfelVector stable;
  stable.reserve(surfels_.size());
  std::copy_if(surfels_.begin(), surfels_.end(), std::back_inserter(stable),
               [this](const Surfel& s) { return isStable(s); });
  return stable;
}

const std::vector<float>& SurfelFusion::pixelWeights(
    const vicc_tracking::PinholeIntrinsics& intrinsics) {
  if (weights_width_ == intrinsics.width && weights_height_ == intrinsics.height) {
    return pixel_weights_;
  }
  weights_width_ = intrinsics.width;
  weights_height_ = intrinsics.height;
  pixel_weights_.resize(static_cast<size_t>(intrinsics.width) * intrinsics.height);
  // gamma = distance to the principal point, normalised by the largest such distance.
  const float max_distance = std::hypot(std::max(intrinsics.cx, intrinsics.width - intrinsics.cx),
                                        std::max(intrinsics.cy, intrinsics.height - intrinsics.cy));
  const float two_sigma_squared =
      static_cast<float>(2.0 * config_.confidence_sigma * config_.confidence_sigma);
  for (int v = 0; v < intrinsics.height; ++v) {
    for (int u = 0; u < intrinsics.width; ++u) {
      const float gamma = std::hypot(u - intrinsics.cx, v - intrinsics.cy) / max_distance;
      pixel_weights_[static_cast<size_t>(v) * intrinsics.width + u] =
          std::exp(-gamma * gamma / two_sigma_squared);
    }
  }
  return pixel_weights_;
}

FusionFrameStats SurfelFusion::integrate(const vicc_tracking::DepthLevel& frame,
                                         const Eigen::Isometry3d& camera_pose,
                                         const cv::Mat1f* intensity) {
  const vicc_tracking::PinholeIntrinsics& intrinsics = frame.intrinsics;
  const size_t pixel_count = static_cast<size_t>(intrinsics.width) * intrinsics.height;
  if (frame.vertices.size() != pixel_count || frame.normals.size() != pixel_count ||
      frame.radii.size() != pixel_count) {
    throw std::invalid_argument("surfel fusion: frame maps do not match its intrinsics");
  }
  if (intensity && (intensity->cols != intrinsics.width || intensity->rows != intrinsics.height)) {
    throw std::invalid_argument("surfel fusion: intensity image size differs from the depth");
  }
  if (!camera_pose.matrix().allFinite()) {
    throw std::invalid_argument("surfel fusion: camera pose is not finite");
  }

  FusionFrameStats stats;
  const int frame_index = frame_index_++;
  const Eigen::Isometry3f pose = camera_pose.cast<float>();
  const Eigen::Matrix3f rotation = pose.linear();
  const Eigen::Vector3f translation = pose.translation();
  const int factor = config_.supersampling;
  if (config_.sort_interval > 0 && frame_index % config_.sort_interval == 0) {
    surfel_order_.sortByPixel(surfels_, pose, intrinsics);
  }
  index_map_.render(surfels_, pose, intrinsics, factor);
  const std::vector<float>& weights = pixelWeights(intrinsics);

  const float max_depth_difference = static_cast<float>(config_.max_depth_difference);
  const float free_space_margin = static_cast<float>(config_.free_space_margin);
  const float max_view_distance = static_cast<float>(config_.max_view_distance);
  const float radius_limit = static_cast<float>(1.0 + config_.max_radius_growth);
  const size_t existing = surfels_.size();
  const int cells_per_pixel = index_map_.cellsPerPixel();
  std::vector<char> remove(existing, 0);
  std::vector<int> seen_through;

  for (int v = 0; v < intrinsics.height; ++v) {
    for (int u = 0; u < intrinsics.width; ++u) {
      const size_t index = static_cast<size_t>(v) * intrinsics.width + u;
      // Pixels without a normal sit on depth edges: neither reliable to fuse nor proof of
      // free space (a flying pixel behind a silhouette would delete the foreground).
      if (!frame.hasNormal(static_cast<int>(index))) continue;
      const Eigen::Vector3f& vertex = frame.vertices[index];
      if (vertex.z() > max_view_distance) continue;
      const Eigen::Vector3f normal_map = rotation * frame.normals[index];

      int best = IndexMap::kEmpty;
      float best_confidence = -1.f;
      int matches[64];  // all candidates that pass the tests (at most factor^2 <= 64)
      int match_count = 0;
      const int* cells = index_map_.pixelCells(u, v);
      // Most cells are empty: find the occupied ones four at a time, then visit only those
      // (in cell order), instead of a data-dependent branch per cell.
      uint64_t occupied = 0;
      int cell = 0;
      for (; cell + 4 <= cells_per_pixel; cell += 4) {
        const vicc_tracking::simd::Mask4 used =
            vicc_tracking::simd::load4(cells + cell) != IndexMap::kEmpty;
        occupied |= static_cast<uint64_t>(vicc_tracking::simd::bits4(used)) << cell;
      }
      for (; cell < cells_per_pixel; ++cell) {
        occupied |= static_cast<uint64_t>(cells[cell] != IndexMap::kEmpty) << cell;
      }
      for (; occupied != 0; occupied &= occupied - 1) {
        const int candidate = cells[__builtin_ctzll(occupied)];
        const Surfel& surfel = surfels_[candidate];
        const float surfel_depth = index_map_.depthOf(surfel);
        if (surfel_depth < vertex.z() - free_space_margin) {
          seen_through.push_back(candidate);
          continue;
        }
        if (std::abs(surfel_depth - vertex.z()) > max_depth_difference) continue;
        if (surfel.normal.dot(normal_map) < min_normal_cosine_) continue;
        matches[match_count++] = candidate;
        if (surfel.confidence > best_confidence) {
          best = candidate;
          best_confidence = surfel.confidence;
        }
      }

      const float weight = weights[index];
      const float radius = frame.radii[index];
      const float measured_intensity = intensity ? (*intensity)(v, u) : 0.f;
      const bool has_intensity = intensity && std::isfinite(measured_intensity);
      if (best != IndexMap::kEmpty) {
        Surfel& surfel = surfels_[best];
        const float c = surfel.confidence;
        if (radius <= radius_limit * surfel.radius) {
          const float inv_total = 1.f / (c + weight);
          const Eigen::Vector3f position = rotation * vertex + translation;
          surfel.position = (c * surfel.position + weight * position) * inv_total;
          surfel.normal = (c * surfel.normal + weight * normal_map).normalized();
          surfel.radius = (c * surfel.radius + weight * radius) * inv_total;
          if (has_intensity) {
            surfel.intensity =
                surfel.hasIntensity()
                    ? (c * surfel.intensity + weight * measured_intensity) * inv_total
                    : measured_intensity;
          }
          ++stats.merged;
        } else {
          ++stats.confirmed;  // a coarser view confirms the surfel without blurring it
        }
        surfel.confidence = c + weight;
        surfel.last_seen = frame_index;
        for (int m = 0; m < match_count; ++m) {
          if (matches[m] != best) mergeDuplicate(matches[m], best, remove, stats);
        }
        continue;
      }
      if (surfels_.size() >= static_cast<size_t>(config_.max_surfels)) {
        ++stats.refused;
        capacity_reached_ = true;
        continue;
      }
      Surfel surfel;
      surfel.position = rotation * vertex + translation;
      surfel.normal = normal_map;
      surfel.radius = radius;
      surfel.confidence = weight;
      surfel.created = frame_index;
      surfel.last_seen = frame_index;
      if (has_intensity) surfel.intensity = measured_intensity;
      surfels_.push_back(surfel);
      ++stats.added;
    }
  }

  // Free space: every violation halves the confidence (the surfel soon drops out of the
  // prediction); it goes once less than one observation's worth is left. A well-observed
  // surface survives a few bad measurements, a surface that has really gone does not.
  for (const int violator : seen_through) {
    Surfel& surfel = surfels_[violator];
    if (remove[violator]) continue;
    surfel.confidence *= 0.5f;
    if (surfel.confidence < 1.f) {
      remove[violator] = 1;
      ++stats.removed_free_space;
    }
  }
  for (size_t i = 0; i < existing; ++i) {
    if (remove[i]) continue;
    const Surfel& surfel = surfels_[i];
    if (!isStable(surfel) && frame_index - surfel.last_seen > config_.unstable_lifetime) {
      remove[i] = 1;
      ++stats.removed_unconfirmed;
    }
  }
  remove.resize(surfels_.size(), 0);  // surfels added this frame stay
  removeMarked(remove);
  return stats;
}

void SurfelFusion::mergeDuplicate(int duplicate, int into, std::vector<char>& remove,
                                  FusionFrameStats& stats) {
  // Keller et al.: points with similar position and normal and overlapping radii are merged.
  // Views from different distances otherwise leave several surfels on one spot, which
  // doubles the model (and the cost of every model prediction) without adding detail.
  if (static_cast<size_t>(duplicate) >= remove.size() || remove[duplicate]) return;
  Surfel& target = surfels_[into];
  const Surfel& other = surfels_[duplicate];
  if ((other.position - target.position).norm() > std::min(target.radius, other.radius)) return;
  const float total = target.confidence + other.confidence;
  target.position =
      (target.confidence * target.position + other.confidence * other.position) / total;
  target.normal =
      (target.confidence * target.normal + other.confidence * other.normal).normalized();
  target.radius = (target.confidence * target.radius + other.confidence * other.radius) / total;
  target.confidence = total;
  target.created = std::min(target.created, other.created);
  remove[duplicate] = 1;
  ++stats.merged_duplicates;
}

void SurfelFusion::removeMarked(const std::vector<char>& remove) {
  // Order does not matter: fill each hole with the last surfel instead of shifting the whole
  // tail (a few removals per frame would otherwise move megabytes).
  size_t end = surfels_.size();
  size_t i = 0;
  while (i < end) {
    if (!remove[i]) {
      ++i;
      continue;
    }
    while (end > i + 1 && remove[end - 1]) --end;  // removed ones at the tail just go
    --end;
    if (i < end) surfels_[i++] = surfels_[end];
  }
  surfels_.resize(end);
}

}  // namespace vicc_fusion
