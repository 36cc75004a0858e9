#pragma once
// The avatar's OGRE scene (the Visual of the Display/Visual split): the skin, one object per
// drawn encoded structure, skin region or proxy (one pick handle each), and the unencoded
// structures, shown only faded where they hide an encoded one; per frame the alternation and
// the view-dependent transparency.
//
// Batching (avatar_view::planBatches), rebuilt only when a status arrives: items that look the
// same share a material and a texture; the skin object leaves out the triangles opaque skin
// regions replace, so the skin is drawn once. View-dependent transparency (thesis 4.4.2.2,
// Fig. 4.3), both parts per frame:
// - per pixel for the skin: SeeThroughStencil (the encoded inner structures are drawn blended
//   over the skin that hides them, nowhere else);
// - per object for the inner context: structures whose projected bounding sphere overlaps
//   an encoded structure's and lie in front of it (avatar_view::findOccluders) are drawn
//   faded over it; the others are not drawn (the opaque skin hides them).

#include <functional>
#include <memory>
#include <string>
#include <vector>

#ifndef Q_MOC_RUN
#include <OGRE/OgreManualObject.h>
#include <OGRE/OgreSceneManager.h>
#include <OGRE/OgreSceneNode.h>
#include <rviz/display_context.h>
#endif

#include "vicc_anatomy_viz/avatar/avatar_model.hpp"
#include "vicc_anatomy_viz/avatar_view/alternation.hpp"
#include "vicc_anatomy_viz/avatar_view/draw_state.hpp"
#include "vicc_anatomy_viz/avatar_view/occlusion.hpp"
#include "vicc_anatomy_viz/avatar_view/render_batches.hpp"
#include "vicc_anatomy_viz/rviz/avatar_materials.hpp"
#include "vicc_anatomy_viz/rviz/see_through_stencil.hpp"
#include "vicc_anatomy_viz/rviz/structure_selection.hpp"

namespace vicc_anatomy_viz::rviz_plugin {

struct VisualOptions {
  bool transparency = true;        ///< view-dependent transparency
  float skin_alpha = 1.f;          ///< skin opacity everywhere
  float see_through_alpha = 0.8f;  ///< opacity of an encoded structure seen through the skin
  double alternation_period_s = 1.5;
  bool relief = true;  ///< the pain trigger's texture lit per pixel (GLSL), else pre-shaded
};

class AvatarVisual {
 public:
  using SelectCallback = std::function<void(const std::string&)>;

  AvatarVisual(rviz::DisplayContext* context, Ogre::SceneNode* parent);
  ~AvatarVisual();

  void setModel(std::shared_ptr<const avatar::AvatarModel> model);
  void setState(const avatar_view::AvatarDrawState& state, const SelectCallback& on_select);
  void setOptions(const VisualOptions& options);
  /// Alternation and occluder fading for the current time and camera.
  void update(double time_s, const avatar_view::CameraModel& camera);
  /// How the current status's normal-perturbation texture is drawn.
  const avatar_view::ReliefStatus& reliefStatus() const { return materials_.reliefStatus(); }

 private:
  struct Encoded {
    Ogre::ManualObject* object = nullptr;
    std::unique_ptr<StructureSelectionHandler> handler;
    bool inner = false;  ///< a structure mesh (under the skin), not a skin mark
    avatar_view::Sphere bounds;
  };
  struct Context {
    Ogre::ManualObject* object = nullptr;  ///< null: the structure has no mesh
    avatar_view::Sphere bounds;
    bool encoded = false;  ///< an encoded object of this structure replaces it
    bool faded = false;    ///< shown faded in front of an encoded structure
  };

  Ogre::ManualObject* newObject(unsigned char queue);
  void destroyObject(Ogre::ManualObject*& object);
  void clearEncoded();
  void rebuildSkin(const std::vector<int>& triangles);
  void buildEncoded(const avatar_view::DrawItem& item, const std::string& material,
                    bool replaces_skin, const SelectCallback& on_select);
  void fadeOccluders(const avatar_view::CameraModel& camera);

  rviz::DisplayContext* context_;
  Ogre::SceneManager* scene_manager_;
  Ogre::SceneNode* node_;
  AvatarMaterials materials_;
  VisualOptions options_;
  std::shared_ptr<const avatar::AvatarModel> model_;
  Ogre::ManualObject* skin_ = nullptr;
  std::vector<int> skin_triangles_;  ///< the skin triangles skin_ holds
  SeeThroughStencil stencil_;
  std::vector<Context> context_structures_;  ///< one per model structure
  avatar_view::AvatarDrawState state_;
  SelectCallback on_select_;
  std::vector<Encoded> encoded_;
  std::unique_ptr<avatar_view::AlternationCycle> cycle_;
  long last_step_ = -1;
};

}  // namespace vicc_anatomy_viz::rviz_plugin
