#include "vicc_anatomy_viz/avatar_view/render_batches.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace vicc_anatomy_viz::avatar_view {
namespace {

bool sameColor(const Rgba& a, const Rgba& b) {
  return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a;
}

bool isInner(const DrawItem& item) { return item.target == TargetKind::kStructureMesh; }

bool opaqueRegion(const DrawItem& item, const avatar::AvatarModel& model) {
  return item.target == TargetKind::kSkinRegion && item.color.a >= kOpaqueAlpha &&
         item.target_index >= 0 &&
         static_cast<std::size_t>(item.target_index) < model.skin_regions.size();
}

/// Whether each item covers its region at every moment: an opaque region item alone, or a
/// member of an alternation group whose members are all opaque items on the same region (one
/// of them is always shown).
std::vector<bool> replacingItems(const AvatarDrawState& state, const avatar::AvatarModel& model) {
  std::map<int, std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < state.items.size(); ++i)
    if (state.items[i].alternation_group >= 0)
      groups[state.items[i].alternation_group].push_back(i);
  std::vector<bool> replaces(state.items.size(), false);
  for (std::size_t i = 0; i < state.items.size(); ++i) {
    const DrawItem& item = state.items[i];
    if (!opaqueRegion(item, model)) continue;
    bool covers = true;
    if (item.alternation_group >= 0) {
      for (std::size_t member : groups[item.alternation_group]) {
        const DrawItem& other = state.items[member];
        covers = covers && opaqueRegion(other, model) && other.target_index == item.target_index;
      }
    }
    replaces[i] = covers;
  }
  return replaces;
}

}  // namespace

bool sameTextureImage(const TextureState& a, const TextureState& b) {
  if (a.kind != b.kind) return false;
  if (a.kind == TextureKind::kNone) return true;
  return a.level == b.level && a.levels == b.levels && a.amplitude == b.amplitude;
}

float seeThroughOpacity(bool transparency, float skin_alpha, float see_through_alpha) {
  const auto unit = [](float value, float fallback) {
    return std::isfinite(value) ? std::clamp(value, 0.f, 1.f) : fallback;
  };
  const float through_skin = 1.f - unit(skin_alpha, 1.f);
  return std::max(through_skin, transparency ? unit(see_through_alpha, 0.8f) : 0.f);
}

bool sameMaterial(const DrawItem& a, const DrawItem& b) {
  return isInner(a) == isInner(b) && sameColor(a.color, b.color) &&
         sameTextureImage(a.texture, b.texture);
}

RenderBatches planBatches(const AvatarDrawState& state, const avatar::AvatarModel& model) {
  RenderBatches batches;
  for (std::size_t i = 0; i < state.items.size(); ++i) {
    const DrawItem& item = state.items[i];
    std::size_t group = 0;
    while (group < batches.materials.size() &&
           !sameMaterial(state.items[batches.materials[group].items.front()], item))
      ++group;
    if (group == batches.materials.size())
      batches.materials.push_back({item.color, item.texture, isInner(item), {}});
    batches.materials[group].items.push_back(i);
    batches.material_of_item.push_back(group);
  }
  batches.replaces_skin = replacingItems(state, model);
  std::vector<bool> covered(model.skin.triangles.size(), false);
  for (std::size_t i = 0; i < state.items.size(); ++i) {
    if (!batches.replaces_skin[i]) continue;
    const auto region = static_cast<std::size_t>(state.items[i].target_index);
    for (int triangle : model.skin_regions[region].triangles)
      if (triangle >= 0 && static_cast<std::size_t>(triangle) < covered.size())
        covered[static_cast<std::size_t>(triangle)] = true;
  }
  for (std::size_t t = 0; t < covered.size(); ++t)
    if (!covered[t]) batches.skin_triangles.push_back(static_cast<int>(t));
  return batches;
}

}  // namespace vicc_anatomy_viz::avatar_view
