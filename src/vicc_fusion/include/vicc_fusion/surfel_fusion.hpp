#pragma once
// Model update of point-based fusion (Keller et al. 2013, thesis 2.2.2 "Model Update", 5.3):
// correspondences through the supersampled index map, confidence-weighted merging, new
// unstable surfels, stability by confidence, removal of unconfirmed and free-space surfels.

#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "vicc_fusion/index_map.hpp"
#include "vicc_fusion/surfel.hpp"
#include "vicc_fusion/surfel_fusion_config.hpp"
#include "vicc_fusion/surfel_order.hpp"
#include "vicc_tracking/depth_preprocessing.hpp"

namespace vicc_fusion {

/// What one model update did.
struct FusionFrameStats {
  int merged = 0;               ///< measurements averaged into a surfel
  int confirmed = 0;            ///< matched, but too coarse (larger radius) to refine it
  int added = 0;                ///< new unstable surfels
  int refused = 0;              ///< new surfels not added: max_surfels reached
  int removed_unconfirmed = 0;  ///< unstable surfels older than unstable_lifetime frames
  int merged_duplicates = 0;    ///< surfels merged into a neighbour they overlap (same surface)
  int removed_free_space = 0;   ///< surfels seen through until < 1 observation's confidence
};

class SurfelFusion {
 public:
  explicit SurfelFusion(const SurfelFusionConfig& config);

  /// Fuses one frame: `frame` is the finest pyramid level of the tracker (undistorted pinhole
  /// grid, camera-frame vertices and normals), camera_pose = T_map_camera. `intensity`
  /// (optional, CV_32FC1 on the same grid) is averaged into the surfels.
  FusionFrameStats integrate(const vicc_tracking::DepthLevel& frame,
                             const Eigen::Isometry3d& camera_pose,
                             const cv::Mat1f* intensity = nullptr);

  void reset();
  /// New thresholds (dynamic_reconfigure) from the next frame on; the model is kept. Throws
  /// std::invalid_argument naming the field; nothing changes then.
  void setConfig(const SurfelFusionConfig& config);

  const SurfelFusionConfig& config() const { return config_; }
  const SurfelVector& surfels() const { return surfels_; }
  bool isStable(const Surfel& surfel) const {
    return surfel.confidence >= config_.stable_confidence;
  }
  size_t stableCount() const;
  size_t unstableCount() const { return surfels_.size() - stableCount(); }
  SurfelVector stableSurfels() const;
  int framesIntegrated() const { return frame_index_; }
  /// True once a new surfel had to be refused because max_surfels was reached.
  bool capacityReached() const { return capacity_reached_; }
  size_t memoryBytes() const { return surfels_.capacity() * sizeof(Surfel); }

 private:
  /// Gaussian measurement weight per pixel (thesis: accuracy falls off with the distance to
  /// the sensor centre), cached per image size.
  const std::vector<float>& pixelWeights(const vicc_tracking::PinholeIntrinsics& intrinsics);
  void mergeDuplicate(int duplicate, int into, std::vector<char>& remove, FusionFrameStats& stats);
  void removeMarked(const std::vector<char>& remove);

  SurfelFusionConfig config_;
  float min_normal_cosine_ = 1.f;
  SurfelVector surfels_;
  IndexMap index_map_;
  SurfelOrder surfel_order_;
  std::vector<float> pixel_weights_;
  int weights_width_ = 0, weights_height_ = 0;
  int frame_index_ = 0;
  bool capacity_reached_ = false;
};

}  // namespace vicc_fusion
