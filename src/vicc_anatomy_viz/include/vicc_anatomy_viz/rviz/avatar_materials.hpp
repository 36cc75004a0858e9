#pragma once
// The avatar's OGRE materials: the skin and the structures without a finding (neutral, no hue
// that could be read as a category), and one material per encoded structure: its colour,
// lit, times its procedural texture, with an optional see-through pass that draws it over
// whatever hides it (view-dependent transparency, see AvatarVisual).

#include <string>
#include <vector>

#include <OGRE/OgreMaterial.h>
#include <OGRE/OgreTexture.h>

#include "vicc_anatomy_viz/avatar_view/draw_state.hpp"

namespace vicc_anatomy_viz::rviz_plugin {

/// Render queue groups: skin and context first, so their depth is known when the encoded
/// structures' see-through pass runs; skin regions and proxies on top of the skin.
constexpr unsigned char kContextQueue = 50;  // Ogre::RENDER_QUEUE_MAIN
constexpr unsigned char kEncodedQueue = 51;
constexpr unsigned char kSkinMarkQueue = 52;

class AvatarMaterials {
 public:
  AvatarMaterials();
  ~AvatarMaterials();
  AvatarMaterials(const AvatarMaterials&) = delete;
  AvatarMaterials& operator=(const AvatarMaterials&) = delete;

  const std::string& skin() const { return skin_; }
  const std::string& context() const { return context_; }
  const std::string& fadedContext() const { return faded_context_; }
  /// Skin opacity (1: opaque) and the opacity of an encoded structure seen through it.
  void setSkinAlpha(float alpha);

  /// A new material for an encoded structure. `see_through_alpha` > 0 adds the pass drawn
  /// without depth test at that opacity.
  std::string encoded(const Rgba& color, const avatar_view::TextureState& texture,
                      float see_through_alpha);
  /// Drops the materials and textures encoded() made (a new status arrived).
  void clearEncoded();

 private:
  std::string uniqueName(const std::string& stem);
  Ogre::TexturePtr texture(const avatar_view::TextureState& texture);

  std::string skin_, context_, faded_context_;
  std::vector<Ogre::MaterialPtr> encoded_;
  std::vector<Ogre::TexturePtr> textures_;
  Ogre::MaterialPtr skin_material_;
  std::vector<Ogre::MaterialPtr> fixed_;
  unsigned counter_ = 0;
};

}  // namespace vicc_anatomy_viz::rviz_plugin
