#include "vicc_anatomy_viz/avatar_view/relief_shading.hpp"

#include <algorithm>
#include <cmath>

#include "vicc_anatomy_viz/avatar_view/procedural_texture.hpp"

namespace vicc_anatomy_viz::avatar_view {
namespace {

constexpr float kPi = 3.14159265f;
/// The tilt factor at full strength: the steepest bumps lean about 45 degrees, enough for the
/// relief to read on a limb a few dozen pixels wide.
constexpr float kFullSlope = 0.75f;
/// A soft highlight on the bumps facing the light: it marks the relief without washing the
/// category's hue out (it adds the same amount to every channel).
constexpr float kSpecular = 0.25f;
constexpr float kShininess = 24.f;

}  // namespace

ReliefParameters reliefParameters(const TextureState& texture) {
  ReliefParameters relief;
  if (texture.kind != TextureKind::kNormalPerturbation) return relief;
  const float strength = textureStrength(texture);
  if (!(strength > 0.f) || !(texture.frequency > 0.f) || !std::isfinite(texture.frequency))
    return relief;
  // `frequency` bumps per decimetre: a bump is half a period of the sine.
  relief.wavenumber = kPi * 10.f * texture.frequency;
  relief.slope = kFullSlope * strength;
  relief.specular = kSpecular;
  relief.shininess = kShininess;
  return relief;
}

float bumpHeight(const Eigen::Vector3f& point, float wavenumber) {
  const Eigen::Vector3f s = (wavenumber * point).array().sin();
  return s.x() * s.y() + s.y() * s.z() + s.z() * s.x();
}

Eigen::Vector3f normalisedBumpGradient(const Eigen::Vector3f& point, float wavenumber) {
  const Eigen::Vector3f s = (wavenumber * point).array().sin();
  const Eigen::Vector3f c = (wavenumber * point).array().cos();
  return {c.x() * (s.y() + s.z()), c.y() * (s.x() + s.z()), c.z() * (s.x() + s.y())};
}

Eigen::Vector3f perturbedNormal(const Eigen::Vector3f& point, const Eigen::Vector3f& normal,
                                const ReliefParameters& relief) {
  if (!relief.active()) return normal;
  const Eigen::Vector3f gradient = normalisedBumpGradient(point, relief.wavenumber);
  const Eigen::Vector3f tangential = gradient - gradient.dot(normal) * normal;
  return (normal - relief.slope * tangential).normalized();
}

Eigen::Vector3f shadeRelief(const Eigen::Vector3f& surface_diffuse,
                            const Eigen::Vector3f& surface_ambient, const Eigen::Vector3f& normal,
                            const ReliefLighting& lighting, const ReliefParameters& relief) {
  const float diffuse = std::max(normal.dot(lighting.to_light), 0.f);
  const Eigen::Vector3f half_vector = (lighting.to_light + lighting.to_eye).normalized();
  const float highlight =
      diffuse > 0.f ? std::pow(std::max(normal.dot(half_vector), 0.f), relief.shininess) : 0.f;
  return surface_ambient.cwiseProduct(lighting.ambient_light) +
         diffuse * surface_diffuse.cwiseProduct(lighting.light) +
         relief.specular * highlight * lighting.light;
}

}  // namespace vicc_anatomy_viz::avatar_view
