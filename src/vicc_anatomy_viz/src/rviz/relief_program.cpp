#include "vicc_anatomy_viz/rviz/relief_program.hpp"

#include <OGRE/OgreGpuProgramManager.h>
#include <OGRE/OgreHighLevelGpuProgram.h>
#include <OGRE/OgreHighLevelGpuProgramManager.h>
#include <OGRE/OgreResourceGroupManager.h>
#include <OGRE/OgreVector.h>

namespace vicc_anatomy_viz::rviz_plugin {
namespace {

const char* const kVertexName = "vicc_avatar/relief.vert";
const char* const kFragmentName = "vicc_avatar/relief.frag";

const char* const kVertexSource = R"(#version 120
uniform mat4 world_view_proj;
varying vec3 surface_position;
varying vec3 surface_normal;
void main() {
  surface_position = gl_Vertex.xyz;
  surface_normal = gl_Normal;
  gl_Position = world_view_proj * gl_Vertex;
}
)";

// avatar_view::perturbedNormal and shadeRelief, per pixel, in object space.
const char* const kFragmentSource = R"(#version 120
uniform vec4 light_position;  // towards a directional light when w = 0
uniform vec4 light_colour;
uniform vec4 ambient_light;
uniform vec4 eye_position;
uniform vec4 surface_diffuse;
uniform vec4 surface_ambient;
uniform vec4 relief;  // wavenumber (rad/m), slope, specular, shininess
varying vec3 surface_position;
varying vec3 surface_normal;

// The normalised gradient of h = sx sy + sy sz + sz sx, s = sin(wavenumber x).
vec3 bumpGradient(vec3 p) {
  vec3 s = sin(relief.x * p);
  vec3 c = cos(relief.x * p);
  return vec3(c.x * (s.y + s.z), c.y * (s.x + s.z), c.z * (s.x + s.y));
}

void main() {
  vec3 normal = normalize(surface_normal);
  vec3 gradient = bumpGradient(surface_position);
  normal = normalize(normal - relief.y * (gradient - dot(gradient, normal) * normal));
  vec3 to_light = normalize(light_position.xyz - surface_position * light_position.w);
  vec3 to_eye = normalize(eye_position.xyz - surface_position);
  float diffuse = max(dot(normal, to_light), 0.0);
  float highlight = 0.0;
  if (diffuse > 0.0)
    highlight = pow(max(dot(normal, normalize(to_light + to_eye)), 0.0), relief.w);
  vec3 colour = surface_ambient.rgb * ambient_light.rgb +
                diffuse * surface_diffuse.rgb * light_colour.rgb +
                relief.z * highlight * light_colour.rgb;
  gl_FragColor = vec4(colour, surface_diffuse.a);
}
)";

using Auto = Ogre::GpuProgramParameters::AutoConstantType;

Ogre::HighLevelGpuProgramPtr compile(const char* name, const char* source,
                                     Ogre::GpuProgramType type) {
  Ogre::HighLevelGpuProgramPtr program =
      Ogre::HighLevelGpuProgramManager::getSingleton().createProgram(
          name, Ogre::ResourceGroupManager::DEFAULT_RESOURCE_GROUP_NAME, "glsl", type);
  program->setSource(source);
  program->load();
  return program;
}

/// The auto constants, set once as the programs' defaults (every pass copies them).
void setDefaults(const Ogre::HighLevelGpuProgramPtr& vertex,
                 const Ogre::HighLevelGpuProgramPtr& fragment) {
  vertex->getDefaultParameters()->setNamedAutoConstant("world_view_proj",
                                                       Auto::ACT_WORLDVIEWPROJ_MATRIX);
  const Ogre::GpuProgramParametersSharedPtr params = fragment->getDefaultParameters();
  params->setNamedAutoConstant("light_position", Auto::ACT_LIGHT_POSITION_OBJECT_SPACE, 0);
  params->setNamedAutoConstant("light_colour", Auto::ACT_LIGHT_DIFFUSE_COLOUR, 0);
  params->setNamedAutoConstant("ambient_light", Auto::ACT_AMBIENT_LIGHT_COLOUR);
  params->setNamedAutoConstant("eye_position", Auto::ACT_CAMERA_POSITION_OBJECT_SPACE);
  params->setNamedAutoConstant("surface_diffuse", Auto::ACT_SURFACE_DIFFUSE_COLOUR);
  params->setNamedAutoConstant("surface_ambient", Auto::ACT_SURFACE_AMBIENT_COLOUR);
}

/// "" when both programs compiled, else why not.
std::string compilePrograms() {
  if (!Ogre::GpuProgramManager::getSingleton().isSyntaxSupported("glsl"))
    return "the render system has no GLSL";
  try {
    const Ogre::HighLevelGpuProgramPtr vertex =
        compile(kVertexName, kVertexSource, Ogre::GPT_VERTEX_PROGRAM);
    const Ogre::HighLevelGpuProgramPtr fragment =
        compile(kFragmentName, kFragmentSource, Ogre::GPT_FRAGMENT_PROGRAM);
    for (const Ogre::HighLevelGpuProgramPtr& program : {vertex, fragment})
      if (program->hasCompileError() || !program->isSupported())
        return "the GLSL program " + program->getName() + " did not compile (see the OGRE log)";
    setDefaults(vertex, fragment);
  } catch (const Ogre::Exception& error) {
    return "the GLSL programs failed: " + error.getDescription();
  }
  return "";
}

}  // namespace

bool reliefProgramsAvailable(std::string& why) {
  static const std::string failure = compilePrograms();
  why = failure;
  return failure.empty();
}

void applyReliefPrograms(Ogre::Pass& pass, const avatar_view::ReliefParameters& relief) {
  pass.setVertexProgram(kVertexName);
  pass.setFragmentProgram(kFragmentName);
  pass.getFragmentProgramParameters()->setNamedConstant(
      "relief", Ogre::Vector4(relief.wavenumber, relief.slope, relief.specular, relief.shininess));
}

}  // namespace vicc_anatomy_viz::rviz_plugin
