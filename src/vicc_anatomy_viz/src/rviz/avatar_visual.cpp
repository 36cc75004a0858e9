#include "vicc_anatomy_viz/rviz/avatar_visual.hpp"

#include <algorithm>

#include "vicc_anatomy_viz/rviz/avatar_meshes.hpp"

namespace vicc_anatomy_viz::rviz_plugin {
namespace {

/// Skin marks over a skin they do not replace sit this far above it (no depth fighting),
/// proxies a little higher.
constexpr float kRegionLift = 0.0015f;
constexpr float kProxyLift = 0.003f;

float innerOpacity(const VisualOptions& options) {
  return avatar_view::seeThroughOpacity(options.transparency, options.skin_alpha,
                                        options.see_through_alpha);
}

}  // namespace

AvatarVisual::AvatarVisual(rviz::DisplayContext* context, Ogre::SceneNode* parent)
    : context_(context),
      scene_manager_(context->getSceneManager()),
      node_(parent->createChildSceneNode()) {
  scene_manager_->addRenderQueueListener(&stencil_);
}

AvatarVisual::~AvatarVisual() {
  clearEncoded();
  for (Context& structure : context_structures_) destroyObject(structure.object);
  destroyObject(skin_);
  scene_manager_->removeRenderQueueListener(&stencil_);
  scene_manager_->destroySceneNode(node_);
}

Ogre::ManualObject* AvatarVisual::newObject(unsigned char queue) {
  Ogre::ManualObject* object = scene_manager_->createManualObject();
  object->setRenderQueueGroup(queue);
  node_->attachObject(object);
  return object;
}

void AvatarVisual::destroyObject(Ogre::ManualObject*& object) {
  if (!object) return;
  node_->detachObject(object);
  scene_manager_->destroyManualObject(object);
  object = nullptr;
}

void AvatarVisual::setModel(std::shared_ptr<const avatar::AvatarModel> model) {
  clearEncoded();
  for (Context& structure : context_structures_) destroyObject(structure.object);
  context_structures_.clear();
  destroyObject(skin_);
  skin_triangles_.clear();
  model_ = std::move(model);
  if (!model_) return;
  for (const avatar::AvatarStructure& structure : model_->structures) {
    Context entry;
    if (!structure.mesh.triangles.empty()) {
      entry.object = newObject(kOccluderQueue);
      addMeshSection(*entry.object, structure.mesh, nullptr, materials_.fadedContext(), 0.f, 0.f);
      entry.object->setVisible(false);
      entry.bounds = avatar_view::boundingSphere(structure.mesh);
    }
    context_structures_.push_back(entry);
  }
  setState(state_, on_select_);
}

void AvatarVisual::rebuildSkin(const std::vector<int>& triangles) {
  if (skin_ && triangles == skin_triangles_) return;
  destroyObject(skin_);
  skin_triangles_ = triangles;
  skin_ = newObject(kSkinQueue);
  addMeshSection(*skin_, model_->skin, &skin_triangles_, materials_.skin(), 0.f, 0.f);
}

void AvatarVisual::clearEncoded() {
  for (Encoded& entry : encoded_) {
    entry.handler.reset();
    destroyObject(entry.object);
  }
  encoded_.clear();
  materials_.clearEncoded();
  for (Context& structure : context_structures_) {
    structure.encoded = structure.faded = false;
    if (structure.object) structure.object->setVisible(false);
  }
}

void AvatarVisual::buildEncoded(const avatar_view::DrawItem& item, const std::string& material,
                                bool replaces_skin, const SelectCallback& on_select) {
  using avatar_view::TargetKind;
  Encoded entry;
  entry.inner = item.target == TargetKind::kStructureMesh;
  const float frequency = item.texture.frequency;
  entry.object = newObject(entry.inner ? kEncodedQueue : kSkinMarkQueue);
  const auto index = static_cast<std::size_t>(item.target_index);
  if (item.target == TargetKind::kSkinRegion) {
    // A region that replaces the skin under it lies exactly on the skin: no seam at its border.
    addMeshSection(*entry.object, model_->skin, &model_->skin_regions[index].triangles, material,
                   replaces_skin ? 0.f : kRegionLift, frequency);
  } else if (item.target == TargetKind::kProxy) {
    addProxyDisc(*entry.object, model_->structures[index].proxy, material, kProxyLift, frequency);
  } else {
    addMeshSection(*entry.object, model_->structures[index].mesh, nullptr, material, 0.f,
                   frequency);
    entry.bounds = avatar_view::boundingSphere(model_->structures[index].mesh);
    // The encoded object replaces the faded one of the same structure.
    context_structures_[index].encoded = true;
  }
  entry.handler = std::make_unique<StructureSelectionHandler>(context_, item.display_name,
                                                              item.overlay_text, on_select);
  entry.handler->addTrackedObject(entry.object);
  encoded_.push_back(std::move(entry));
}

void AvatarVisual::setState(const avatar_view::AvatarDrawState& state,
                            const SelectCallback& on_select) {
  clearEncoded();
  state_ = state;
  on_select_ = on_select;
  cycle_ = std::make_unique<avatar_view::AlternationCycle>(state_, options_.alternation_period_s);
  last_step_ = -1;
  if (!model_) return;
  const avatar_view::RenderBatches batches = avatar_view::planBatches(state_, *model_);
  const std::vector<std::string> materials = materials_.setEncoded(batches.materials);
  rebuildSkin(batches.skin_triangles);
  for (std::size_t i = 0; i < state_.items.size(); ++i)
    buildEncoded(state_.items[i], materials[batches.material_of_item[i]], batches.replaces_skin[i],
                 on_select);
}

void AvatarVisual::setOptions(const VisualOptions& options) {
  const bool rebuild = options.alternation_period_s != options_.alternation_period_s ||
                       options.relief != options_.relief;
  options_ = options;
  materials_.setReliefEnabled(options_.relief);
  materials_.setSkinAlpha(options_.skin_alpha);
  materials_.setInnerOpacity(innerOpacity(options_));
  stencil_.setEnabled(innerOpacity(options_) > 0.f);
  if (rebuild) setState(state_, on_select_);
}

void AvatarVisual::fadeOccluders(const avatar_view::CameraModel& camera) {
  std::vector<avatar_view::Sphere> targets;
  for (const Encoded& entry : encoded_)
    if (entry.inner && entry.object->getVisible()) targets.push_back(entry.bounds);
  std::vector<avatar_view::Sphere> candidates;
  for (const Context& structure : context_structures_) candidates.push_back(structure.bounds);
  std::vector<bool> occludes(candidates.size(), false);
  if (options_.transparency && !targets.empty())
    occludes = avatar_view::findOccluders(targets, candidates, camera);
  for (std::size_t i = 0; i < context_structures_.size(); ++i) {
    Context& structure = context_structures_[i];
    const bool faded = occludes[i] && !structure.encoded;
    if (!structure.object || structure.faded == faded) continue;
    structure.faded = faded;
    structure.object->setVisible(faded);
  }
}

void AvatarVisual::update(double time_s, const avatar_view::CameraModel& camera) {
  if (cycle_) {
    const long step = cycle_->step(time_s);
    if (step != last_step_) {
      last_step_ = step;
      for (std::size_t i = 0; i < encoded_.size(); ++i)
        encoded_[i].object->setVisible(cycle_->shown(i, time_s));
    }
  }
  fadeOccluders(camera);
}

}  // namespace vicc_anatomy_viz::rviz_plugin
