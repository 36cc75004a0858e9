#include "vicc_anatomy_viz/rviz/avatar_materials.hpp"

#include <OGRE/OgreImage.h>
#include <OGRE/OgreMaterialManager.h>
#include <OGRE/OgrePass.h>
#include <OGRE/OgreTechnique.h>
#include <OGRE/OgreTextureManager.h>

#include <algorithm>
#include <utility>

#include "vicc_anatomy_viz/avatar_view/procedural_texture.hpp"

namespace vicc_anatomy_viz::rviz_plugin {
namespace {

const Ogre::String& kGroup = Ogre::ResourceGroupManager::DEFAULT_RESOURCE_GROUP_NAME;
constexpr int kTextureSize = 128;

/// Lit, double sided off, with ambient = diffuse so the side away from the light keeps
/// its hue readable.
void setLitColour(Ogre::Pass& pass, const Ogre::ColourValue& colour) {
  pass.setLightingEnabled(true);
  pass.setDiffuse(colour);
  pass.setAmbient(Ogre::ColourValue(colour.r * 0.6f, colour.g * 0.6f, colour.b * 0.6f));
  pass.setSpecular(Ogre::ColourValue(0.1f, 0.1f, 0.1f, colour.a));
  pass.setShininess(8.f);
}

void setBlend(Ogre::Pass& pass, float alpha) {
  if (alpha < 0.999f) {
    pass.setSceneBlending(Ogre::SBT_TRANSPARENT_ALPHA);
    pass.setDepthWriteEnabled(false);
  } else {
    pass.setSceneBlending(Ogre::SBT_REPLACE);
    pass.setDepthWriteEnabled(true);
  }
}

Ogre::MaterialPtr plainMaterial(const std::string& name, const Ogre::ColourValue& colour) {
  Ogre::MaterialPtr material = Ogre::MaterialManager::getSingleton().create(name, kGroup);
  Ogre::Pass& pass = *material->getTechnique(0)->getPass(0);
  setLitColour(pass, colour);
  setBlend(pass, colour.a);
  return material;
}

}  // namespace

AvatarMaterials::AvatarMaterials() {
  skin_ = uniqueName("skin");
  skin_see_through_ = uniqueName("skin_see_through");
  context_ = uniqueName("context");
  faded_context_ = uniqueName("faded_context");
  skin_material_ = plainMaterial(skin_, Ogre::ColourValue(0.86f, 0.86f, 0.84f, 1.f));
  skin_see_through_material_ =
      plainMaterial(skin_see_through_, Ogre::ColourValue(0.86f, 0.86f, 0.84f, 0.2f));
  fixed_ = {skin_material_, skin_see_through_material_,
            plainMaterial(context_, Ogre::ColourValue(0.74f, 0.72f, 0.70f, 1.f)),
            plainMaterial(faded_context_, Ogre::ColourValue(0.74f, 0.72f, 0.70f, 0.25f))};
}

AvatarMaterials::~AvatarMaterials() {
  clearEncoded();
  for (const auto& material : fixed_) Ogre::MaterialManager::getSingleton().remove(material);
}

std::string AvatarMaterials::uniqueName(const std::string& stem) {
  static unsigned instances = 0;
  if (counter_ == 0) counter_ = ++instances * 100000;
  return "vicc_avatar/" + stem + "/" + std::to_string(counter_++);
}

void AvatarMaterials::setSkinAlpha(float skin_alpha, float see_through_alpha) {
  const std::pair<Ogre::MaterialPtr, float> skins[] = {
      {skin_material_, skin_alpha},
      {skin_see_through_material_, std::min(skin_alpha, 1.f - see_through_alpha)}};
  for (const auto& [material, alpha] : skins) {
    Ogre::Pass& pass = *material->getTechnique(0)->getPass(0);
    Ogre::ColourValue colour = pass.getDiffuse();
    colour.a = alpha;
    pass.setDiffuse(colour);
    setBlend(pass, alpha);
    // A see-through skin still hides what lies behind it from later (skin mark) passes.
    pass.setDepthWriteEnabled(true);
  }
}

Ogre::TexturePtr AvatarMaterials::texture(const avatar_view::TextureState& state) {
  const avatar_view::GreyImage grey = avatar_view::textureImage(state, kTextureSize);
  Ogre::Image image;
  image.loadDynamicImage(const_cast<Ogre::uchar*>(grey.pixels.data()), grey.size, grey.size, 1,
                         Ogre::PF_L8);
  Ogre::TexturePtr texture =
      Ogre::TextureManager::getSingleton().loadImage(uniqueName("texture"), kGroup, image);
  textures_.push_back(texture);
  return texture;
}

std::string AvatarMaterials::encoded(const Rgba& color, const avatar_view::TextureState& state) {
  const std::string name = uniqueName("encoded");
  Ogre::MaterialPtr material =
      plainMaterial(name, Ogre::ColourValue(color.r, color.g, color.b, color.a));
  Ogre::Pass& pass = *material->getTechnique(0)->getPass(0);
  if (state.kind != avatar_view::TextureKind::kNone)
    pass.createTextureUnitState()->setTexture(texture(state));
  material->load();
  encoded_.push_back(material);
  return name;
}

void AvatarMaterials::clearEncoded() {
  for (const auto& material : encoded_) Ogre::MaterialManager::getSingleton().remove(material);
  for (const auto& texture : textures_) Ogre::TextureManager::getSingleton().remove(texture);
  encoded_.clear();
  textures_.clear();
}

}  // namespace vicc_anatomy_viz::rviz_plugin
