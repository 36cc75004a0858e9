#pragma once
// A grey level per surfel from its normal, for rviz (the cloud's "rgb" field): Lambert
// shading under a fixed light, two-sided, so that the surface's shape shows whatever its
// height. The height colouring (AxisColor) hides the shape of a scanned body.

#include <Eigen/Core>

#include <cstdint>

namespace vicc_fusion {

struct SurfelShading {
  /// Towards the light, in the cloud's frame (normalised on use): above, a little to the side.
  Eigen::Vector3f light{0.6f, 0.45f, 0.66f};
  float ambient = 0.25f;  ///< grey level of a surface edge-on to the light
};

/// Grey level 0..1 for a unit normal; a zero or non-finite normal gets the ambient level.
float shadedGrey(const Eigen::Vector3f& normal, const SurfelShading& shading = {});

/// The grey level as rviz's packed "rgb" (0x00RRGGBB, read as the bytes of a float32).
std::uint32_t packedGrey(float grey);

}  // namespace vicc_fusion
