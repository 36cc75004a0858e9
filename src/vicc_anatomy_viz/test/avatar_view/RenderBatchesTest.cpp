#include <gtest/gtest.h>

#include <cmath>

#include "synthetic_avatar.hpp"
#include "vicc_anatomy_viz/avatar_view/render_batches.hpp"

namespace vicc_anatomy_viz::avatar_view {
namespace {

using testing::syntheticAvatar;

DrawItem item(TargetKind target, int index, Rgba color, int group = -1) {
  DrawItem drawn;
  drawn.target = target;
  drawn.target_index = index;
  drawn.color = color;
  drawn.alternation_group = group;
  return drawn;
}

const Rgba kRed{1.f, 0.f, 0.f, 1.f};
const Rgba kCyan{0.f, 0.8f, 0.8f, 1.f};
const Rgba kPaleRed{1.f, 0.f, 0.f, 0.5f};

TEST(RenderBatchesTest, EveryItemIsInExactlyOneMaterialWithItsColour) {
  AvatarDrawState state;
  state.items = {item(TargetKind::kSkinRegion, 0, kRed), item(TargetKind::kSkinRegion, 1, kRed),
                 item(TargetKind::kStructureMesh, 0, kRed), item(TargetKind::kProxy, 1, kCyan),
                 item(TargetKind::kSkinRegion, 1, kCyan)};
  const RenderBatches batches = planBatches(state, syntheticAvatar());
  ASSERT_EQ(batches.material_of_item.size(), state.items.size());
  // red on the skin (two regions), red inner (see-through, its own material), cyan on the skin.
  ASSERT_EQ(batches.materials.size(), 3u);
  std::vector<int> seen(state.items.size(), 0);
  for (std::size_t m = 0; m < batches.materials.size(); ++m) {
    for (std::size_t i : batches.materials[m].items) {
      ++seen[i];
      EXPECT_EQ(batches.material_of_item[i], m);
      EXPECT_FLOAT_EQ(batches.materials[m].color.g, state.items[i].color.g);
      EXPECT_EQ(batches.materials[m].inner, state.items[i].target == TargetKind::kStructureMesh);
    }
  }
  for (int count : seen) EXPECT_EQ(count, 1);
  EXPECT_EQ(batches.material_of_item[0], batches.material_of_item[1]);
  EXPECT_NE(batches.material_of_item[0], batches.material_of_item[2]);
  EXPECT_EQ(batches.material_of_item[3], batches.material_of_item[4]);
}

TEST(RenderBatchesTest, TexturesShareAMaterialOnlyWithTheSameImage) {
  DrawItem a = item(TargetKind::kSkinRegion, 0, kRed);
  a.texture = {TextureKind::kNoise, 2, 3, 8.f, 0.6f};
  DrawItem b = a;
  b.texture.frequency = 4.f;  // only the texture coordinates differ
  DrawItem c = a;
  c.texture.level = 3;
  DrawItem d = a;
  d.texture.kind = TextureKind::kNormalPerturbation;
  EXPECT_TRUE(sameMaterial(a, b));
  EXPECT_FALSE(sameMaterial(a, c));
  EXPECT_FALSE(sameMaterial(a, d));
  EXPECT_FALSE(sameMaterial(a, item(TargetKind::kSkinRegion, 0, kPaleRed)));
}

TEST(RenderBatchesTest, OpaqueRegionsReplaceTheSkinTrianglesTheyCover) {
  AvatarDrawState state;
  state.items = {item(TargetKind::kSkinRegion, 1, kRed),
                 item(TargetKind::kStructureMesh, 0, kCyan)};
  RenderBatches batches = planBatches(state, syntheticAvatar());
  EXPECT_EQ(batches.replaces_skin, (std::vector<bool>{true, false}));
  EXPECT_EQ(batches.skin_triangles, std::vector<int>{0});  // region 1 is triangle 1
  // A translucent region lets the skin show through: the skin stays under it.
  state.items[0].color = kPaleRed;
  batches = planBatches(state, syntheticAvatar());
  EXPECT_EQ(batches.replaces_skin, (std::vector<bool>{false, false}));
  EXPECT_EQ(batches.skin_triangles, (std::vector<int>{0, 1}));
}

TEST(RenderBatchesTest, AnAlternationReplacesTheSkinOnlyIfEveryMemberCoversTheSameRegion) {
  AvatarDrawState state;
  state.items = {item(TargetKind::kSkinRegion, 0, kRed, 4),
                 item(TargetKind::kSkinRegion, 0, kCyan, 4)};
  EXPECT_EQ(planBatches(state, syntheticAvatar()).skin_triangles, std::vector<int>{1});
  // While the translucent member is shown the skin must be there.
  state.items[1].color.a = 0.5f;
  EXPECT_EQ(planBatches(state, syntheticAvatar()).skin_triangles, (std::vector<int>{0, 1}));
  // A member elsewhere (a proxy) leaves the region bare while it is shown.
  state.items[1] = item(TargetKind::kProxy, 1, kCyan, 4);
  EXPECT_EQ(planBatches(state, syntheticAvatar()).skin_triangles, (std::vector<int>{0, 1}));
}

TEST(RenderBatchesTest, OutOfRangeTargetsNeverRemoveSkin) {
  AvatarDrawState state;
  state.items = {item(TargetKind::kSkinRegion, 7, kRed), item(TargetKind::kSkinRegion, -1, kRed)};
  const RenderBatches batches = planBatches(state, syntheticAvatar());
  EXPECT_EQ(batches.skin_triangles, (std::vector<int>{0, 1}));
  EXPECT_EQ(batches.materials.size(), 1u);
}

TEST(RenderBatchesTest, SeeThroughOpacityFollowsTransparencyAndSkinAlpha) {
  // View-dependent transparency: the see-through alpha; off with an opaque skin: hidden.
  EXPECT_FLOAT_EQ(seeThroughOpacity(true, 1.f, 0.8f), 0.8f);
  EXPECT_FLOAT_EQ(seeThroughOpacity(false, 1.f, 0.8f), 0.f);
  // A translucent skin lets its share through either way, whichever is more.
  EXPECT_FLOAT_EQ(seeThroughOpacity(false, 0.3f, 0.8f), 0.7f);
  EXPECT_FLOAT_EQ(seeThroughOpacity(true, 0.3f, 0.5f), 0.7f);
  EXPECT_FLOAT_EQ(seeThroughOpacity(true, 0.9f, 0.5f), 0.5f);
  // Out of range is clamped; not finite counts as the default.
  EXPECT_FLOAT_EQ(seeThroughOpacity(true, 2.f, 1.5f), 1.f);
  EXPECT_FLOAT_EQ(seeThroughOpacity(false, std::nanf(""), 0.8f), 0.f);
  EXPECT_FLOAT_EQ(seeThroughOpacity(true, 1.f, std::nanf("")), 0.8f);
}

}  // namespace
}  // namespace vicc_anatomy_viz::avatar_view
