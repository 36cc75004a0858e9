#include "vicc_anatomy_viz/rviz/avatar_materials.hpp"

#include <OGRE/OgreException.h>
#include <OGRE/OgreImage.h>
#include <OGRE/OgreMaterialManager.h>
#include <OGRE/OgrePass.h>
#include <OGRE/OgreTechnique.h>
#include <OGRE/OgreTextureManager.h>

#include <algorithm>

#include "vicc_anatomy_viz/avatar_view/procedural_texture.hpp"
#include "vicc_anatomy_viz/avatar_view/relief_shading.hpp"
#include "vicc_anatomy_viz/rviz/relief_program.hpp"

namespace vicc_anatomy_viz::rviz_plugin {
namespace {

const Ogre::String& kGroup = Ogre::ResourceGroupManager::DEFAULT_RESOURCE_GROUP_NAME;
constexpr int kTextureSize = 128;

/// Lit, with ambient 0.6 x diffuse so the side away from the light keeps its hue readable.
void setLitColour(Ogre::Pass& pass, const Ogre::ColourValue& colour) {
  pass.setLightingEnabled(true);
  pass.setDiffuse(colour);
  pass.setAmbient(Ogre::ColourValue(colour.r * 0.6f, colour.g * 0.6f, colour.b * 0.6f));
  pass.setSpecular(Ogre::ColourValue(0.1f, 0.1f, 0.1f, colour.a));
  pass.setShininess(8.f);
}

Ogre::Pass& firstPass(const Ogre::MaterialPtr& material) {
  return *material->getTechnique(0)->getPass(0);
}

/// Blended without depth writes below kOpaqueAlpha (OGRE then sorts it back to front).
void setAlpha(Ogre::Pass& pass, float alpha) {
  Ogre::ColourValue colour = pass.getDiffuse();
  colour.a = alpha;
  pass.setDiffuse(colour);
  const bool opaque = alpha >= avatar_view::kOpaqueAlpha;
  pass.setSceneBlending(opaque ? Ogre::SBT_REPLACE : Ogre::SBT_TRANSPARENT_ALPHA);
  pass.setDepthWriteEnabled(opaque);
}

Ogre::MaterialPtr plainMaterial(const std::string& name, const Ogre::ColourValue& colour) {
  Ogre::MaterialPtr material = Ogre::MaterialManager::getSingleton().create(name, kGroup);
  setLitColour(firstPass(material), colour);
  setAlpha(firstPass(material), colour.a);
  return material;
}

}  // namespace

AvatarMaterials::AvatarMaterials() {
  skin_ = uniqueName("skin");
  faded_context_ = uniqueName("faded_context");
  skin_material_ = plainMaterial(skin_, Ogre::ColourValue(0.86f, 0.86f, 0.84f, 1.f));
  faded_context_material_ =
      plainMaterial(faded_context_, Ogre::ColourValue(0.74f, 0.72f, 0.70f, 0.25f));
}

AvatarMaterials::~AvatarMaterials() {
  clearEncoded();
  Ogre::MaterialManager::getSingleton().remove(skin_material_);
  Ogre::MaterialManager::getSingleton().remove(faded_context_material_);
}

std::string AvatarMaterials::uniqueName(const std::string& stem) {
  static unsigned instances = 0;
  if (counter_ == 0) counter_ = ++instances * 100000;
  return "vicc_avatar/" + stem + "/" + std::to_string(counter_++);
}

void AvatarMaterials::setSkinAlpha(float skin_alpha) {
  Ogre::Pass& pass = firstPass(skin_material_);
  setAlpha(pass, skin_alpha);
  // A translucent skin still hides what lies behind it from the skin marks.
  pass.setDepthWriteEnabled(true);
}

Ogre::TexturePtr AvatarMaterials::texture(const avatar_view::TextureState& state) {
  for (const auto& [made, texture] : textures_)
    if (avatar_view::sameTextureImage(made, state)) return texture;
  const avatar_view::GreyImage grey = avatar_view::textureImage(state, kTextureSize);
  Ogre::Image image;
  image.loadDynamicImage(const_cast<Ogre::uchar*>(grey.pixels.data()), grey.size, grey.size, 1,
                         Ogre::PF_L8);
  Ogre::TexturePtr texture =
      Ogre::TextureManager::getSingleton().loadImage(uniqueName("texture"), kGroup, image);
  textures_.emplace_back(state, texture);
  return texture;
}

void AvatarMaterials::applyInnerOpacity(Encoded& encoded) const {
  if (!encoded.inner) return;
  Ogre::Pass& pass = firstPass(encoded.material);
  setAlpha(pass,
           inner_opacity_ > 0.f ? encoded.alpha * std::min(inner_opacity_, 1.f) : encoded.alpha);
  // Blended but depth-writing: the faded structures in front of it are depth-tested against it.
  pass.setDepthWriteEnabled(true);
}

void AvatarMaterials::applyTexture(const Ogre::MaterialPtr& material,
                                   const avatar_view::TextureState& state) {
  if (state.kind == avatar_view::TextureKind::kNone) return;
  Ogre::Pass& pass = firstPass(material);
  const avatar_view::ReliefParameters relief = avatar_view::reliefParameters(state);
  if (relief.active()) {
    relief_status_.needed = true;
    std::string why;
    if (!relief_enabled_) {
      relief_status_.fallback_reason = "per-pixel relief switched off";
    } else if (!reliefProgramsAvailable(why)) {
      relief_status_.fallback_reason = why;
      relief_status_.unavailable = true;
    } else {
      try {
        applyReliefPrograms(pass, relief);
        material->load();
        if (!material->getSupportedTechniques().empty()) {
          relief_status_.per_pixel = true;
          return;
        }
        relief_status_.fallback_reason = "the relief programs are not supported here: " +
                                         material->getUnsupportedTechniquesExplanation();
      } catch (const Ogre::Exception& error) {
        relief_status_.fallback_reason = "the relief programs failed: " + error.getDescription();
      }
      relief_status_.unavailable = true;
      pass.setVertexProgram("");
      pass.setFragmentProgram("");
    }
  }
  pass.createTextureUnitState()->setTexture(texture(state));
  if (material->isLoaded()) material->compile();
}

std::vector<std::string> AvatarMaterials::setEncoded(
    const std::vector<avatar_view::MaterialGroup>& groups) {
  clearEncoded();
  std::vector<std::string> names;
  for (const avatar_view::MaterialGroup& group : groups) {
    names.push_back(uniqueName("encoded"));
    const Rgba& c = group.color;
    Encoded encoded{plainMaterial(names.back(), Ogre::ColourValue(c.r, c.g, c.b, c.a)), c.a,
                    group.inner};
    applyTexture(encoded.material, group.texture);
    applyInnerOpacity(encoded);
    encoded.material->load();
    encoded_.push_back(encoded);
  }
  // Per pixel only if every relief material got its programs.
  if (!relief_status_.fallback_reason.empty()) relief_status_.per_pixel = false;
  return names;
}

void AvatarMaterials::setInnerOpacity(float opacity) {
  inner_opacity_ = opacity;
  for (Encoded& encoded : encoded_) applyInnerOpacity(encoded);
}

void AvatarMaterials::clearEncoded() {
  for (const auto& encoded : encoded_)
    Ogre::MaterialManager::getSingleton().remove(encoded.material);
  for (const auto& entry : textures_) Ogre::TextureManager::getSingleton().remove(entry.second);
  encoded_.clear();
  textures_.clear();
  relief_status_ = avatar_view::ReliefStatus{};
}

}  // namespace vicc_anatomy_viz::rviz_plugin
