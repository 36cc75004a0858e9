#pragma once
// The avatar's OGRE materials: the skin (opaque, and see-through for the pixels where it hides
// an encoded structure) and the structures without a finding (neutral, no hue that could be
// read as a category), and one material per encoded structure: its colour, lit, times its
// procedural texture.

#include <string>
#include <vector>

#include <OGRE/OgreMaterial.h>
#include <OGRE/OgreTexture.h>

#include "vicc_anatomy_viz/avatar_view/draw_state.hpp"

namespace vicc_anatomy_viz::rviz_plugin {

/// Render queue groups, in drawing order (see SeeThroughStencil): encoded inner structures,
/// the opaque skin, context structures (after the skin, so the depth test drops them where
/// the skin hides them: most of their pixels are never shaded), the see-through skin, skin
/// marks (regions, proxies).
constexpr unsigned char kEncodedQueue = 60;
constexpr unsigned char kSkinQueue = 61;
constexpr unsigned char kContextQueue = 62;
constexpr unsigned char kSkinSeeThroughQueue = 63;
constexpr unsigned char kSkinMarkQueue = 64;

class AvatarMaterials {
 public:
  AvatarMaterials();
  ~AvatarMaterials();
  AvatarMaterials(const AvatarMaterials&) = delete;
  AvatarMaterials& operator=(const AvatarMaterials&) = delete;

  const std::string& skin() const { return skin_; }
  const std::string& skinSeeThrough() const { return skin_see_through_; }
  const std::string& context() const { return context_; }
  const std::string& fadedContext() const { return faded_context_; }
  /// Skin opacity (1: opaque) and the opacity of an encoded structure seen through it.
  void setSkinAlpha(float skin_alpha, float see_through_alpha);

  /// A new material for an encoded structure.
  std::string encoded(const Rgba& color, const avatar_view::TextureState& texture);
  /// Drops the materials and textures encoded() made (a new status arrived).
  void clearEncoded();

 private:
  std::string uniqueName(const std::string& stem);
  Ogre::TexturePtr texture(const avatar_view::TextureState& texture);

  std::string skin_, skin_see_through_, context_, faded_context_;
  std::vector<Ogre::MaterialPtr> encoded_;
  std::vector<Ogre::TexturePtr> textures_;
  Ogre::MaterialPtr skin_material_, skin_see_through_material_;
  std::vector<Ogre::MaterialPtr> fixed_;
  unsigned counter_ = 0;
};

}  // namespace vicc_anatomy_viz::rviz_plugin
