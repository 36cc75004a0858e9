#pragma once
// The GLSL programs of the pain trigger's relief (avatar_view/relief_shading.hpp has the same
// formulas and their tests): a vertex program passing the object-space position and normal,
// and a fragment program that tilts the normal by the solid bump field and lights the pixel
// with the scene's first light (rviz's head light). GLSL 1.20, as rviz's own shaders, for
// OGRE 1.12's GL render system (Mesa llvmpipe included).

#include <string>

#include <OGRE/OgrePass.h>

#include "vicc_anatomy_viz/avatar_view/relief_shading.hpp"

namespace vicc_anatomy_viz::rviz_plugin {

/// Compiles and links the programs once per process. False, with the reason in `why`, when the
/// render system has no GLSL or the programs do not compile: the caller then keeps the
/// pre-shaded texture.
bool reliefProgramsAvailable(std::string& why);

/// Makes `pass` draw the relief: the programs and their parameters (the pass's own diffuse,
/// ambient and alpha stay the colour, so changing them later needs no new program set-up).
/// Requires reliefProgramsAvailable().
void applyReliefPrograms(Ogre::Pass& pass, const avatar_view::ReliefParameters& relief);

}  // namespace vicc_anatomy_viz::rviz_plugin
