#include "vicc_anatomy_viz/avatar_view/draw_state.hpp"

#include <cmath>
#include <map>
#include <set>
#include <utility>

#include "vicc_anatomy_viz/time_format.hpp"

namespace vicc_anatomy_viz::avatar_view {
namespace {

using Key = std::pair<std::string, Side>;

bool unitInterval(float value) { return std::isfinite(value) && value >= 0.f && value <= 1.f; }

bool validColor(const Rgba& color) {
  return unitInterval(color.r) && unitInterval(color.g) && unitInterval(color.b) &&
         unitInterval(color.a);
}

std::string describe(const EncodedStructure& entry) {
  return entry.category + " on " + entry.structure_id + " (" + toString(entry.side) + ")";
}

/// Lookup tables of the model, built once per status.
class ModelIndex {
 public:
  explicit ModelIndex(const avatar::AvatarModel& model) : model_(model) {
    for (std::size_t i = 0; i < model.structures.size(); ++i)
      structures_.emplace(Key{model.structures[i].structure_id, model.structures[i].side}, i);
    for (std::size_t i = 0; i < model.skin_regions.size(); ++i)
      regions_.emplace(Key{model.skin_regions[i].structure_id, model.skin_regions[i].side}, i);
  }

  /// Where an entry is drawn; false (with `why`) when the model cannot show it.
  bool place(const EncodedStructure& entry, DrawItem& item, std::string& why) const {
    const Key key{entry.structure_id, entry.side};
    if (auto region = regions_.find(key); region != regions_.end()) {
      item.target = TargetKind::kSkinRegion;
      item.target_index = static_cast<int>(region->second);
      if (model_.skin_regions[region->second].triangles.empty()) {
        why = "skin region " + entry.structure_id + " has no triangles";
        return false;
      }
      return true;
    }
    const auto found = structures_.find(key);
    if (found == structures_.end()) {
      why = "the avatar has no structure " + entry.structure_id + " (" + toString(entry.side) + ")";
      return false;
    }
    const avatar::AvatarStructure& structure = model_.structures[found->second];
    item.target_index = static_cast<int>(found->second);
    const bool has_mesh = !structure.mesh.triangles.empty();
    // A proxy where the encoding asks for one; a structure without a mesh only has its proxy.
    if (structure.has_proxy && (entry.proxy || !has_mesh)) {
      item.target = TargetKind::kProxy;
      return true;
    }
    item.target = TargetKind::kStructureMesh;
    if (!has_mesh) why = "structure " + entry.structure_id + " has neither mesh nor proxy";
    return has_mesh;
  }

 private:
  const avatar::AvatarModel& model_;
  std::map<Key, std::size_t> structures_;
  std::map<Key, std::size_t> regions_;
};

bool readTexture(const EncodedStructure& entry, TextureState& texture, std::string& why) {
  if (!textureKindFromId(entry.texture_id, texture.kind)) {
    why = "unknown texture '" + entry.texture_id + "'";
    return false;
  }
  if (texture.kind == TextureKind::kNone || entry.texture_level <= 0) {
    texture = TextureState{};
    return true;
  }
  texture.level = entry.texture_level;
  texture.levels = entry.texture_levels;
  texture.frequency = static_cast<float>(entry.texture_frequency);
  texture.amplitude = static_cast<float>(entry.texture_amplitude);
  const bool finite = std::isfinite(texture.frequency) && std::isfinite(texture.amplitude);
  if (!finite || texture.level > texture.levels || texture.frequency <= 0.f ||
      texture.amplitude < 0.f) {
    why = "invalid texture parameters";
    return false;
  }
  return true;
}

std::set<std::string> hiddenCategories(const EncodedStatus& status) {
  std::set<std::string> hidden(status.hidden_categories.begin(), status.hidden_categories.end());
  for (const LegendEntry& entry : status.legend)
    if (!entry.visible) hidden.insert(entry.id);
  return hidden;
}

std::string headline(const EncodedStatus& status) {
  if (!status.has_examination) {
    const std::string date = status.requested_date.empty() ? "now" : status.requested_date;
    return status.patient_id + ": no examination at or before " + date;
  }
  std::string text = status.patient_id + "  " + formatTimestamp(status.examination_time);
  if (status.examination_status == ExaminationStatus::kPreliminary) text += "  PRELIMINARY";
  if (status.partial) text += "  PARTIAL (" + status.partial_reason + ")";
  return text;
}

std::vector<LegendLine> legendLines(const EncodedStatus& status) {
  std::vector<LegendLine> lines;
  for (const LegendEntry& entry : status.legend) {
    LegendLine line;
    line.label = entry.label + " (" + entry.hue_name + "): " + std::to_string(entry.count);
    if (!entry.visible) line.label += " [hidden]";
    line.color = validColor(entry.color) ? entry.color : Rgba{0.5f, 0.5f, 0.5f, 1.f};
    line.visible = entry.visible;
    lines.push_back(line);
  }
  return lines;
}

/// Where entry `index` stands in the alternation's view order; -1 when it is not listed.
int alternationRank(const Alternation& alternation, std::size_t index) {
  for (std::size_t rank = 0; rank < alternation.entries.size(); ++rank)
    if (alternation.entries[rank] == index) return static_cast<int>(rank);
  return -1;
}

}  // namespace

bool textureKindFromId(const std::string& id, TextureKind& kind) {
  if (id.empty())
    kind = TextureKind::kNone;
  else if (id == "normal_perturbation")
    kind = TextureKind::kNormalPerturbation;
  else if (id == "noise")
    kind = TextureKind::kNoise;
  else
    return false;
  return true;
}

AvatarDrawState buildDrawState(const EncodedStatus& status, const avatar::AvatarModel& model) {
  AvatarDrawState state;
  state.headline = headline(status);
  state.legend = legendLines(status);
  if (!status.has_examination) state.warnings.push_back(state.headline);
  const ModelIndex index(model);
  const std::set<std::string> hidden = hiddenCategories(status);
  for (std::size_t i = 0; i < status.structures.size(); ++i) {
    const EncodedStructure& entry = status.structures[i];
    if (hidden.count(entry.category)) continue;
    DrawItem item;
    item.entry = i;
    item.structure_id = entry.structure_id;
    item.side = entry.side;
    item.category = entry.category;
    item.display_name = entry.display_name;
    item.overlay_text = entry.overlay_text;
    item.color = entry.color;
    std::string why;
    if (!validColor(entry.color)) why = "colour is not a valid RGBA in [0, 1]";
    if (why.empty()) index.place(entry, item, why);
    if (why.empty()) readTexture(entry, item.texture, why);
    if (!why.empty()) {
      state.warnings.push_back("not drawn: " + describe(entry) + ": " + why);
      continue;
    }
    const int group = entry.alternation_group;
    const int rank = group >= 0 && group < static_cast<int>(status.alternations.size())
                         ? alternationRank(status.alternations[static_cast<std::size_t>(group)], i)
                         : -1;
    if (group != -1 && rank < 0) {
      state.warnings.push_back("alternation group " + std::to_string(group) + " of " +
                               describe(entry) + " does not list it; drawn without alternation");
    } else {
      item.alternation_group = group;
      item.alternation_rank = rank;
    }
    state.items.push_back(std::move(item));
  }
  return state;
}

}  // namespace vicc_anatomy_viz::avatar_view
