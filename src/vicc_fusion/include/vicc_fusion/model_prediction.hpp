#pragma once
// Model prediction (Keller et al., thesis 2.2.2): the stable surfels rendered at a camera pose
// into vertex and normal maps, so the next frame is aligned frame-to-model.

#include <Eigen/Geometry>

#include "vicc_fusion/surfel.hpp"
#include "vicc_tracking/depth_preprocessing.hpp"

namespace vicc_fusion {

struct ModelPredictionConfig {
  double stable_confidence = 3.0;  ///< only surfels at or above this confidence are drawn
  /// Surfel radii just cover a regular grid (half the pixel diagonal), so rounding leaves
  /// pinholes; drawing the discs a little larger closes them (the blend averages overlaps).
  double splat_radius_scale = 1.1;
  double blend_depth = 0.005;        ///< m; discs this close to the front one are averaged
  double max_splat_radius_px = 6.0;  ///< caps the footprint of very close surfels
  double min_depth = 0.1;            ///< m; nearer surfels are not drawn
  void validate() const;
};

/// Splats the stable surfels seen from camera_pose = T_map_camera as discs of their radius
/// (ray-disc intersection per pixel, z-buffered; discs within blend_depth of the front one
/// are averaged with their confidence as weight) into the grid of `intrinsics`.
/// Vertices and normals are in camera coordinates; pixels no disc covers are invalid.
vicc_tracking::DepthLevel renderModel(const SurfelVector& surfels,
                                      const Eigen::Isometry3d& camera_pose,
                                      const vicc_tracking::PinholeIntrinsics& intrinsics,
                                      const ModelPredictionConfig& config);

/// The prediction as an ICP reference pyramid laid out like `frame` (same level count and
/// intrinsics): level 0 rendered, coarser levels downsampled from its depth.
vicc_tracking::DepthPyramid predictPyramid(const SurfelVector& surfels,
                                           const Eigen::Isometry3d& camera_pose,
                                           const vicc_tracking::DepthPyramid& frame,
                                           const vicc_tracking::PreprocessingConfig& preprocessing,
                                           const ModelPredictionConfig& config);

}  // namespace vicc_fusion
