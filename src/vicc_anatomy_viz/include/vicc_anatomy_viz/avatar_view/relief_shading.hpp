#pragma once
// The normal-perturbation texture (pain trigger, thesis Table 4.1) as per-pixel relief: a solid
// bump field in the avatar's frame tilts the surface normal before the scene's light shades
// it, so the bumps read as relief from any side, without texture coordinates or seams. The
// rviz display runs the same formulas in a GLSL fragment program (rviz/relief_program.cpp);
// here they are the reference for unit tests and the shader's parameters.

#include <Eigen/Core>

#include <string>

#include "vicc_anatomy_viz/avatar_view/draw_state.hpp"

namespace vicc_anatomy_viz::avatar_view {

/// The relief shader's parameters of one texture state.
struct ReliefParameters {
  float wavenumber = 0;  ///< rad per metre: one bump per pi / wavenumber along each axis
  float slope = 0;       ///< normal tilt per unit of the normalised bump gradient
  float specular = 0;    ///< highlight on the bumps facing the light, times the light colour
  float shininess = 1;
  bool active() const { return slope > 0 && wavenumber > 0; }
};

/// How the normal-perturbation texture of the current status is drawn.
/// (The display reports it; the materials fill it in.)
struct ReliefStatus {
  bool needed = false;          ///< some encoded item has a normal-perturbation texture
  bool per_pixel = false;       ///< drawn by the GLSL relief programs
  std::string fallback_reason;  ///< why not (needed and not per pixel)
  bool unavailable = false;     ///< the reason is a missing or failing shader, not a choice
};

/// A normal-perturbation state's relief: one bump per 1 / `frequency` decimetre, tilt growing
/// with amplitude x level / levels; inactive for every other texture.
ReliefParameters reliefParameters(const TextureState& texture);

/// The bump field h = sx sy + sy sz + sz sx (s = sin of wavenumber x coordinate), in [-1, 3],
/// never flat on a whole plane (unlike a single product), and its gradient divided by the
/// wavenumber (magnitude at most 2).
float bumpHeight(const Eigen::Vector3f& point, float wavenumber);
Eigen::Vector3f normalisedBumpGradient(const Eigen::Vector3f& point, float wavenumber);

/// The shading normal: `normal` (unit) tilted against the tangential part of the gradient, as
/// a height field raised by h has it.
Eigen::Vector3f perturbedNormal(const Eigen::Vector3f& point, const Eigen::Vector3f& normal,
                                const ReliefParameters& relief);

/// One light, as the fragment program shades a pixel: surface ambient x ambient light +
/// surface diffuse x light x max(n.l, 0) + specular x light x Blinn-Phong highlight.
struct ReliefLighting {
  Eigen::Vector3f ambient_light = Eigen::Vector3f::Zero();
  Eigen::Vector3f light = Eigen::Vector3f::Ones();
  Eigen::Vector3f to_light = Eigen::Vector3f::UnitZ();  ///< unit
  Eigen::Vector3f to_eye = Eigen::Vector3f::UnitZ();    ///< unit
};
Eigen::Vector3f shadeRelief(const Eigen::Vector3f& surface_diffuse,
                            const Eigen::Vector3f& surface_ambient, const Eigen::Vector3f& normal,
                            const ReliefLighting& lighting, const ReliefParameters& relief);

}  // namespace vicc_anatomy_viz::avatar_view
