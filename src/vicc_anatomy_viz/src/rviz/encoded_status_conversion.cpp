#include "vicc_anatomy_viz/rviz/encoded_status_conversion.hpp"

#include "vicc_anatomy_viz/time_format.hpp"

namespace vicc_anatomy_viz::rviz_plugin {
namespace {

Rgba fromMessage(const std_msgs::ColorRGBA& color) { return {color.r, color.g, color.b, color.a}; }

Side readSide(const std::string& text, const std::string& where,
              std::vector<std::string>& warnings) {
  if (const auto side = sideFromString(text)) return *side;
  warnings.push_back(where + ": unknown side '" + text + "'");
  return Side::kNone;
}

EncodedStructure fromMessage(const vicc_msgs::EncodedStructure& msg,
                             std::vector<std::string>& warnings) {
  EncodedStructure entry;
  entry.structure_id = msg.structure_id;
  entry.side = readSide(msg.side, msg.structure_id, warnings);
  entry.structure_class = msg.structure_class;
  entry.display_name = msg.display_name;
  entry.fma_id = msg.fma_id;
  entry.category = msg.category;
  entry.color = fromMessage(msg.color);
  entry.hue_deg = msg.hue_deg;
  entry.saturation = msg.saturation;
  entry.brightness = msg.brightness;
  entry.intensity_level = msg.intensity_level;
  entry.intensity_levels = msg.intensity_levels;
  entry.texture_id = msg.texture_id;
  entry.texture_level = msg.texture_level;
  entry.texture_levels = msg.texture_levels;
  entry.texture_frequency = msg.texture_frequency;
  entry.texture_amplitude = msg.texture_amplitude;
  entry.proxy = msg.proxy;
  entry.overlay_text = msg.overlay_text;
  for (const auto& prop : msg.properties) {
    entry.properties.push_back({prop.prop_type, prop.label, prop.value, prop.derived_value,
                                prop.visual_variable, prop.level, prop.level_count,
                                prop.normal != 0});
  }
  entry.alternation_group = msg.alternation_group;
  return entry;
}

}  // namespace

EncodedStatus fromMessage(const vicc_msgs::EncodedStatus& msg, std::vector<std::string>& warnings) {
  EncodedStatus status;
  status.patient_id = msg.patient_id;
  status.view_id = msg.view_id;
  status.requested_date = msg.requested_date;
  status.has_examination = msg.has_examination;
  if (msg.has_examination) {
    if (const auto time = parseTimestamp(msg.examination_time))
      status.examination_time = *time;
    else
      warnings.push_back("unreadable examination time '" + msg.examination_time + "'");
  }
  status.examination_status =
      examinationStatusFromString(msg.examination_status).value_or(ExaminationStatus::kPreliminary);
  status.partial = msg.examination_partial;
  status.partial_reason = msg.partial_reason;
  for (const auto& structure : msg.structures)
    status.structures.push_back(fromMessage(structure, warnings));
  for (const auto& alternation : msg.alternations) {
    Alternation entry;
    entry.structure_id = alternation.structure_id;
    entry.side = readSide(alternation.side, alternation.structure_id, warnings);
    entry.display_name = alternation.display_name;
    entry.categories = alternation.categories;
    entry.entries.assign(alternation.entries.begin(), alternation.entries.end());
    status.alternations.push_back(entry);
  }
  for (const auto& legend : msg.legend) {
    status.legend.push_back({legend.id, legend.label, legend.hue_name, fromMessage(legend.color),
                             static_cast<bool>(legend.visible), legend.count});
  }
  status.hidden_categories = msg.hidden_categories;
  status.notes = msg.notes;
  return status;
}

}  // namespace vicc_anatomy_viz::rviz_plugin
