#pragma once
// How the avatar display batches one draw state for the GPU (software rasterisers are bound
// by fill rate and per-draw overhead): encoded items that look the same share one material
// (and one texture), and the skin pass leaves out the skin triangles that an opaque skin
// region item replaces, so no skin pixel is drawn twice. Qt- and OGRE-free for unit tests.

#include <cstddef>
#include <vector>

#include "vicc_anatomy_viz/avatar_view/draw_state.hpp"

namespace vicc_anatomy_viz::avatar_view {

/// One material: a colour, a texture and whether it lies under the skin (an inner structure,
/// drawn see-through) or on it (a skin region or proxy).
struct MaterialGroup {
  Rgba color;
  TextureState texture;
  bool inner = false;
  std::vector<std::size_t> items;  ///< indices into AvatarDrawState::items, ascending
};

struct RenderBatches {
  std::vector<MaterialGroup> materials;
  std::vector<std::size_t> material_of_item;  ///< per state item: index into `materials`
  /// Per state item: a skin region drawn in place of the skin triangles it covers (opaque,
  /// shown at every moment of its alternation), so it needs no lift above the skin.
  std::vector<bool> replaces_skin;
  /// The skin triangles the skin pass still draws (ascending indices into skin.triangles).
  std::vector<int> skin_triangles;
};

/// Alpha at or above this counts as opaque.
constexpr float kOpaqueAlpha = 0.999f;

/// Same texture image: kind, level, levels and amplitude (the frequency only scales texture
/// coordinates).
bool sameTextureImage(const TextureState& a, const TextureState& b);

/// Same material: equal colour, equal texture image (kind, level, levels, amplitude; the
/// frequency only scales texture coordinates) and the same placement (inner or on the skin).
bool sameMaterial(const DrawItem& a, const DrawItem& b);

/// How opaque the encoded inner structures are drawn over the skin that hides them: the
/// see-through alpha with view-dependent transparency, at least what a translucent skin lets
/// through (1 - skin alpha); 0 when neither (the opaque skin hides them). Inputs are clamped
/// to [0, 1]; a non-finite one counts as its default (skin 1, see-through 0.8).
float seeThroughOpacity(bool transparency, float skin_alpha, float see_through_alpha);

/// The batches of `state` on `model` (items whose target index is out of range are left out
/// of every batch's skin replacement but still get a material).
RenderBatches planBatches(const AvatarDrawState& state, const avatar::AvatarModel& model);

}  // namespace vicc_anatomy_viz::avatar_view
