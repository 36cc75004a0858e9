#pragma once
// The two texture visual variables as grey modulation images (multiplied with the structure's
// colour, so the hue stays the category's): the normal-perturbation texture (pain trigger) is
// a bump field shaded by a fixed light; the noise texture (paresthesia) is block noise whose
// contrast grows with the level. Tiles repeat seamlessly.

#include <Eigen/Core>

#include <cstdint>
#include <vector>

#include "vicc_anatomy_viz/avatar_view/draw_state.hpp"

namespace vicc_anatomy_viz::avatar_view {

/// Pattern cells in one texture tile along each axis.
constexpr int kTextureCellsPerTile = 8;

struct GreyImage {
  int size = 0;                      ///< square, size x size pixels
  std::vector<std::uint8_t> pixels;  ///< row-major luminance
};

/// How strong a texture state is, in [0, 1]: its amplitude, scaled by how far up its levels
/// it is (the lowest level keeps a third, so it stays visible); 0 without a level.
float textureStrength(const TextureState& texture);

/// The modulation image of a texture state (kNone: a plain white tile). `size` is rounded up
/// to a multiple of kTextureCellsPerTile.
GreyImage textureImage(const TextureState& texture, int size);

/// Texture coordinates of a surface point: planar projection on the two axes across the
/// dominant normal axis, scaled so `frequency` cells fall on each decimetre of surface.
Eigen::Vector2f textureCoordinate(const Eigen::Vector3f& position, const Eigen::Vector3f& normal,
                                  float frequency);

}  // namespace vicc_anatomy_viz::avatar_view
