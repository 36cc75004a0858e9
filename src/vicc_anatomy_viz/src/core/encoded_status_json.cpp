#include "vicc_anatomy_viz/encoded_status_json.hpp"

#include <cmath>
#include <utility>

#include "vicc_anatomy_viz/time_format.hpp"

namespace vicc_anatomy_viz {

namespace {

using nlohmann::json;

/// Rounded so that the JSON stays readable and stable across platforms.
double rounded(double value) { return std::round(value * 1e4) / 1e4; }

json toJson(const Rgba& color) {
  return json::array({rounded(color.r), rounded(color.g), rounded(color.b), rounded(color.a)});
}

json toJson(const EncodedStructure& entry) {
  json properties = json::array();
  for (const auto& prop : entry.properties) {
    json encoded = {{"prop_type", prop.prop_type}, {"label", prop.label},
                    {"value", prop.value},         {"visual_variable", prop.visual_variable},
                    {"level", prop.level},         {"level_count", prop.level_count},
                    {"normal", prop.normal}};
    if (!prop.derived_value.empty()) encoded["derived_value"] = prop.derived_value;
    properties.push_back(std::move(encoded));
  }
  json texture = nullptr;
  if (!entry.texture_id.empty()) {
    texture = {{"id", entry.texture_id},
               {"level", entry.texture_level},
               {"levels", entry.texture_levels},
               {"frequency", rounded(entry.texture_frequency)},
               {"amplitude", rounded(entry.texture_amplitude)}};
  }
  return {{"structure_id", entry.structure_id},
          {"side", toString(entry.side)},
          {"structure_class", entry.structure_class},
          {"display_name", entry.display_name},
          {"fma_id", entry.fma_id},
          {"category", entry.category},
          {"rgba", toJson(entry.color)},
          {"hsv", json::array({rounded(entry.hue_deg), rounded(entry.saturation),
                               rounded(entry.brightness)})},
          {"intensity_level", entry.intensity_level},
          {"intensity_levels", entry.intensity_levels},
          {"texture", std::move(texture)},
          {"proxy", entry.proxy},
          {"overlay_text", entry.overlay_text},
          {"properties", std::move(properties)},
          {"alternation_group", entry.alternation_group}};
}

}  // namespace

nlohmann::json toJson(const EncodedStatus& status) {
  json structures = json::array();
  for (const auto& entry : status.structures) structures.push_back(toJson(entry));
  json alternations = json::array();
  for (const auto& alternation : status.alternations) {
    alternations.push_back({{"structure_id", alternation.structure_id},
                            {"side", toString(alternation.side)},
                            {"display_name", alternation.display_name},
                            {"categories", alternation.categories},
                            {"entries", alternation.entries}});
  }
  json legend = json::array();
  for (const auto& entry : status.legend) {
    legend.push_back({{"id", entry.id},
                      {"label", entry.label},
                      {"hue", entry.hue_name},
                      {"rgba", toJson(entry.color)},
                      {"visible", entry.visible},
                      {"count", entry.count}});
  }
  return {{"format", "vicc-encoded-status"},
          {"version", 1},
          {"patient_id", status.patient_id},
          {"view_id", status.view_id},
          {"requested_date", status.requested_date},
          {"has_examination", status.has_examination},
          {"examination_time",
           status.has_examination ? json(formatTimestamp(status.examination_time)) : json(nullptr)},
          {"examination_status",
           status.has_examination ? json(toString(status.examination_status)) : json(nullptr)},
          {"examination_partial", status.partial},
          {"partial_reason", status.partial_reason},
          {"structures", std::move(structures)},
          {"alternations", std::move(alternations)},
          {"legend", std::move(legend)},
          {"hidden_categories", status.hidden_categories},
          {"notes", status.notes}};
}

}  // namespace vicc_anatomy_viz
