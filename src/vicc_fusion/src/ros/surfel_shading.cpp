#include "vicc_fusion/ros/surfel_shading.hpp"

#include <algorithm>
#include <cmath>

namespace vicc_fusion {

float shadedGrey(const Eigen::Vector3f& normal, const SurfelShading& shading) {
  const float length = normal.norm();
  const float light_length = shading.light.norm();
  if (!std::isfinite(length) || length < 1e-6f || !(light_length > 1e-6f)) return shading.ambient;
  // Two-sided: a surfel's normal may face either way of the light.
  const float lambert = std::fabs(normal.dot(shading.light)) / (length * light_length);
  return std::clamp(shading.ambient + (1.f - shading.ambient) * lambert, 0.f, 1.f);
}

std::uint32_t packedGrey(float grey) {
  const auto level = static_cast<std::uint32_t>(std::lround(std::clamp(grey, 0.f, 1.f) * 255.f));
  return (level << 16) | (level << 8) | level;
}

}  // namespace vicc_fusion
