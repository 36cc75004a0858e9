#pragma once
// The avatar's OGRE materials: the skin, the faded look of an unencoded structure that hides
// an encoded one, and one material per group of encoded items that look the same
// (avatar_view::planBatches): their colour, lit, times their procedural texture. The pain
// trigger's normal perturbation is lit per pixel by GLSL programs (relief_program.hpp); where
// they are switched off or unavailable it falls back to the pre-shaded bump texture.

#include <string>
#include <vector>

#include <OGRE/OgreMaterial.h>
#include <OGRE/OgreTexture.h>

#include "vicc_anatomy_viz/avatar_view/relief_shading.hpp"
#include "vicc_anatomy_viz/avatar_view/render_batches.hpp"

namespace vicc_anatomy_viz::rviz_plugin {

/// Render queue groups, in drawing order (see SeeThroughStencil): the opaque skin (without
/// the triangles opaque skin regions replace), skin marks (regions, proxies) depth-tested
/// against it, the encoded inner structures (drawn over what hides them when seen through),
/// and the faded unencoded structures in front of them.
constexpr unsigned char kSkinQueue = 60;
constexpr unsigned char kSkinMarkQueue = 61;
constexpr unsigned char kEncodedQueue = 62;
constexpr unsigned char kOccluderQueue = 63;

class AvatarMaterials {
 public:
  AvatarMaterials();
  ~AvatarMaterials();
  AvatarMaterials(const AvatarMaterials&) = delete;
  AvatarMaterials& operator=(const AvatarMaterials&) = delete;

  const std::string& skin() const { return skin_; }
  const std::string& fadedContext() const { return faded_context_; }
  void setSkinAlpha(float skin_alpha);

  /// New materials for `groups` (the previous status's are dropped); the name of each group's.
  /// Groups with the same texture image share one texture.
  std::vector<std::string> setEncoded(const std::vector<avatar_view::MaterialGroup>& groups);
  /// How opaque the inner encoded structures are drawn over what hides them (times their own
  /// alpha); 0: not seen through, depth-ordered as they lie.
  void setInnerOpacity(float opacity);
  void clearEncoded();
  /// Whether setEncoded may use the GLSL relief (else the pre-shaded texture).
  void setReliefEnabled(bool enabled) { relief_enabled_ = enabled; }
  const avatar_view::ReliefStatus& reliefStatus() const { return relief_status_; }

 private:
  struct Encoded {
    Ogre::MaterialPtr material;
    float alpha = 1.f;  ///< the encoded colour's own alpha
    bool inner = false;
  };
  std::string uniqueName(const std::string& stem);
  Ogre::TexturePtr texture(const avatar_view::TextureState& texture);
  void applyInnerOpacity(Encoded& encoded) const;
  /// Gives `material` its texture: the relief programs when they can be used, else the image.
  void applyTexture(const Ogre::MaterialPtr& material, const avatar_view::TextureState& state);

  std::string skin_, faded_context_;
  Ogre::MaterialPtr skin_material_, faded_context_material_;
  std::vector<Encoded> encoded_;
  std::vector<std::pair<avatar_view::TextureState, Ogre::TexturePtr>> textures_;
  float inner_opacity_ = 0.f;
  bool relief_enabled_ = true;
  avatar_view::ReliefStatus relief_status_;
  unsigned counter_ = 0;
};

}  // namespace vicc_anatomy_viz::rviz_plugin
