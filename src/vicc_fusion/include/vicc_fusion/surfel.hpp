#pragma once
// The point-based model of Keller et al. 2013 (thesis 2.2.2, 5.3): surfels with a confidence
// counter that makes them "stable" once observed often enough.

#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Core>

namespace vicc_fusion {

struct Surfel {
  Eigen::Vector3f position = Eigen::Vector3f::Zero();  ///< map frame, m
  Eigen::Vector3f normal = Eigen::Vector3f::UnitZ();   ///< map frame, unit
  float radius = 0.f;                                  ///< m
  float confidence = 0.f;  ///< sum of the measurement weights merged into it
  int created = 0;         ///< frame index of the first observation
  int last_seen = 0;       ///< frame index of the last merge
  /// Gray value (pico flexx amplitude image) when a topic provides it, NaN otherwise.
  float intensity = std::numeric_limits<float>::quiet_NaN();

  bool hasIntensity() const { return !std::isnan(intensity); }
};

using SurfelVector = std::vector<Surfel>;

}  // namespace vicc_fusion
