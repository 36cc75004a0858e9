#pragma once
// The ground-truth surface a recording saw: the scene's surface sampled densely, kept where
// at least one depth frame of the trajectory sees it (in range, in the image, not occluded,
// facing the camera). Reconstruction accuracy and completeness are measured against it.

#include <string>
#include <vector>

#include "vicc_tracking/sim/rig_simulator.hpp"

namespace vicc_tracking::sim {

struct VisibleSurfaceConfig {
  double spacing = 0.002;             ///< m between samples
  int frame_stride = 3;               ///< test every n-th depth frame (neighbours see the same)
  double occlusion_tolerance = 0.01;  ///< m between a sample and the rendered depth
  /// What counts as "seen" for completeness: a close-range scan (thesis: 0.5-0.8 m to the
  /// object) resolves surfaces up to about this distance; further away a pico flexx pixel
  /// covers more than the 5 mm completeness radius.
  double max_distance = 1.0;          ///< m
  double max_view_angle_deg = 70.0;   ///< grazing views beyond this do not count as seen
};

/// Samples of the true surface seen by the rig's depth camera, map frame, outward normals.
/// Calls `progress(done, total)` after each tested frame when given.
std::vector<SurfacePoint> visibleSurface(const RigSimulator& rig,
                                         const VisibleSurfaceConfig& config,
                                         void (*progress)(size_t, size_t) = nullptr);

/// Binary little-endian PLY with x y z nx ny nz curvature (float, curvature 0); throws
/// std::runtime_error on failure.
void writeSurfacePly(const std::string& path, const std::vector<SurfacePoint>& points);

}  // namespace vicc_tracking::sim
