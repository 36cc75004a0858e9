#include "vicc_anatomy_viz/avatar_view/procedural_texture.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <random>

namespace vicc_anatomy_viz::avatar_view {
namespace {

constexpr float kPi = 3.14159265f;
/// The darkest modulation: the category's hue stays readable inside the pattern.
constexpr float kDarkest = 0.45f;

std::uint8_t toByte(float value) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(value, 0.f, 1.f) * 255.f));
}

/// Bumps h = sin(u) sin(v) per cell; the surface normal of the scaled height field lit from
/// the upper left gives the shading.
void fillBumps(GreyImage& image, float amount) {
  const Eigen::Vector3f light = Eigen::Vector3f(-0.5f, -0.5f, 0.7f).normalized();
  const float scale = 2.f * kPi * kTextureCellsPerTile / static_cast<float>(image.size);
  for (int y = 0; y < image.size; ++y) {
    for (int x = 0; x < image.size; ++x) {
      const float u = scale * (x + 0.5f), v = scale * (y + 0.5f);
      const float dhdx = amount * std::cos(u) * std::sin(v);
      const float dhdy = amount * std::sin(u) * std::cos(v);
      const Eigen::Vector3f normal = Eigen::Vector3f(-dhdx, -dhdy, 1.f).normalized();
      const float lit = std::max(0.f, normal.dot(light)) / light.z();
      image.pixels[y * image.size + x] = toByte(kDarkest + (1.f - kDarkest) * std::min(lit, 1.f));
    }
  }
}

/// One random grey per cell, the darkest cells darker with a stronger texture.
void fillNoise(GreyImage& image, float amount, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> uniform(0.f, 1.f);
  const int cell = image.size / kTextureCellsPerTile;
  std::vector<float> cells(kTextureCellsPerTile * kTextureCellsPerTile);
  for (float& value : cells) value = 1.f - amount * (1.f - kDarkest) * uniform(random);
  for (int y = 0; y < image.size; ++y)
    for (int x = 0; x < image.size; ++x)
      image.pixels[y * image.size + x] =
          toByte(cells[(y / cell) * kTextureCellsPerTile + x / cell]);
}

}  // namespace

float textureStrength(const TextureState& texture) {
  if (texture.levels <= 0 || texture.level <= 0) return 0.f;
  const float level = static_cast<float>(texture.level) / static_cast<float>(texture.levels);
  return std::clamp(texture.amplitude, 0.f, 1.f) * std::max(level, 0.34f);
}

GreyImage textureImage(const TextureState& texture, int size) {
  GreyImage image;
  const int cells = kTextureCellsPerTile;
  image.size = std::max(cells, (size + cells - 1) / cells * cells);
  image.pixels.assign(static_cast<std::size_t>(image.size) * image.size, 255);
  const float amount = textureStrength(texture);
  if (texture.kind == TextureKind::kNormalPerturbation) fillBumps(image, 3.f * amount);
  if (texture.kind == TextureKind::kNoise) fillNoise(image, amount, 46u + texture.level);
  return image;
}

Eigen::Vector2f textureCoordinate(const Eigen::Vector3f& position, const Eigen::Vector3f& normal,
                                  float frequency) {
  const float tiles_per_metre = 10.f * frequency / static_cast<float>(kTextureCellsPerTile);
  int axis = 0;
  normal.cwiseAbs().maxCoeff(&axis);
  const int first = (axis + 1) % 3, second = (axis + 2) % 3;
  return Eigen::Vector2f(position[first], position[second]) * tiles_per_metre;
}

}  // namespace vicc_anatomy_viz::avatar_view
