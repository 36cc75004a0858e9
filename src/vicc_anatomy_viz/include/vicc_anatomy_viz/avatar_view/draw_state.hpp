#pragma once
// What the avatar draws for one encoded status (thesis 4.3.3): per encoded structure the
// geometry it lands on (a structure mesh, a dermatome skin region or a proxy disc), its colour,
// texture and alternation group; plus warnings for everything that could not be drawn
// faithfully. Qt-, OGRE- and ROS-free so the rules are unit tested.

#include <string>
#include <vector>

#include "vicc_anatomy_viz/avatar/avatar_model.hpp"
#include "vicc_anatomy_viz/status_encoder.hpp"

namespace vicc_anatomy_viz::avatar_view {

enum class TextureKind { kNone, kNormalPerturbation, kNoise };

/// "" -> kNone, "normal_perturbation", "noise"; anything else is reported by the caller.
bool textureKindFromId(const std::string& id, TextureKind& kind);

struct TextureState {
  TextureKind kind = TextureKind::kNone;
  int level = 0;  ///< 1..levels; 0 = no texture
  int levels = 0;
  float frequency = 0.f;  ///< pattern repetitions per metre of skin
  float amplitude = 0.f;  ///< 0..1 strength of the perturbation
};

enum class TargetKind { kStructureMesh, kSkinRegion, kProxy };

struct DrawItem {
  std::size_t entry = 0;  ///< index into EncodedStatus::structures
  TargetKind target = TargetKind::kStructureMesh;
  int target_index = -1;  ///< into AvatarModel::structures (mesh, proxy) or ::skin_regions
  std::string structure_id;
  Side side = Side::kNone;
  std::string category;
  std::string display_name;
  Rgba color;
  TextureState texture;
  int alternation_group = -1;  ///< -1: alone on its structure
  int alternation_rank = 0;    ///< position in the group's view order (the first is shown first)
  std::string overlay_text;    ///< name + raw values, shown when the structure is clicked
};

struct LegendLine {
  std::string label;  ///< e.g. "Radicular pain (red): 1"
  Rgba color;
  bool visible = true;
};

struct AvatarDrawState {
  std::vector<DrawItem> items;
  std::vector<LegendLine> legend;
  std::vector<std::string> warnings;  ///< one line per problem, shown in the display's status
  std::string headline;               ///< patient, examination time, final/preliminary, partial
};

/// Maps an encoded status onto the avatar. Never throws on bad status content: an entry naming
/// a structure the model lacks, a NaN or out-of-range colour, an unknown texture or an
/// alternation index out of range is left out with a warning, the rest is drawn.
AvatarDrawState buildDrawState(const EncodedStatus& status, const avatar::AvatarModel& model);

}  // namespace vicc_anatomy_viz::avatar_view
