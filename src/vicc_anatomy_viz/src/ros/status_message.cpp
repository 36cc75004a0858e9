#include "vicc_anatomy_viz/ros/status_message.hpp"

#include <algorithm>

#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/time_format.hpp"

namespace vicc_anatomy_viz::ros_adapter {

namespace {

std_msgs::ColorRGBA toMessage(const Rgba& color) {
  std_msgs::ColorRGBA msg;
  msg.r = color.r;
  msg.g = color.g;
  msg.b = color.b;
  msg.a = color.a;
  return msg;
}

std::uint8_t small(int value) { return static_cast<std::uint8_t>(std::clamp(value, 0, 255)); }

vicc_msgs::EncodedStructure toMessage(const EncodedStructure& entry) {
  vicc_msgs::EncodedStructure msg;
  msg.structure_id = entry.structure_id;
  msg.side = toString(entry.side);
  msg.structure_class = entry.structure_class;
  msg.display_name = entry.display_name;
  msg.fma_id = entry.fma_id;
  msg.category = entry.category;
  msg.color = toMessage(entry.color);
  msg.hue_deg = static_cast<float>(entry.hue_deg);
  msg.saturation = static_cast<float>(entry.saturation);
  msg.brightness = static_cast<float>(entry.brightness);
  msg.intensity_level = small(entry.intensity_level);
  msg.intensity_levels = small(entry.intensity_levels);
  msg.texture_id = entry.texture_id;
  msg.texture_level = small(entry.texture_level);
  msg.texture_levels = small(entry.texture_levels);
  msg.texture_frequency = static_cast<float>(entry.texture_frequency);
  msg.texture_amplitude = static_cast<float>(entry.texture_amplitude);
  msg.proxy = entry.proxy;
  msg.overlay_text = entry.overlay_text;
  for (const auto& prop : entry.properties) {
    vicc_msgs::EncodedProperty p;
    p.prop_type = prop.prop_type;
    p.label = prop.label;
    p.value = prop.value;
    p.derived_value = prop.derived_value;
    p.visual_variable = prop.visual_variable;
    p.level = small(prop.level);
    p.level_count = small(prop.level_count);
    p.normal = prop.normal;
    msg.properties.push_back(p);
  }
  msg.alternation_group = entry.alternation_group;
  return msg;
}

}  // namespace

ros::Time rosTime(TimestampUs time) {
  // ros::Time starts in 1970 and ends in 2106; examination_time (text) is exact for all times.
  const std::int64_t seconds = wholeSeconds(time);
  if (seconds < 0 || seconds > 0xffffffffLL) return ros::Time();
  return ros::Time(static_cast<std::uint32_t>(seconds),
                   static_cast<std::uint32_t>(microsWithinSecond(time) * 1000));
}

vicc_msgs::EncodedStatus toMessage(const EncodedStatus& status) {
  vicc_msgs::EncodedStatus msg;
  msg.patient_id = status.patient_id;
  msg.view_id = status.view_id;
  msg.requested_date = status.requested_date;
  msg.has_examination = status.has_examination;
  if (status.has_examination) {
    msg.examination_time = formatTimestamp(status.examination_time);
    msg.examination_stamp = rosTime(status.examination_time);
    msg.examination_status = toString(status.examination_status);
    msg.examination_partial = status.partial;
    msg.partial_reason = status.partial_reason;
  }
  for (const auto& entry : status.structures) msg.structures.push_back(toMessage(entry));
  for (const auto& alternation : status.alternations) {
    vicc_msgs::Alternation a;
    a.structure_id = alternation.structure_id;
    a.side = toString(alternation.side);
    a.display_name = alternation.display_name;
    a.categories = alternation.categories;
    for (const auto index : alternation.entries)
      a.entries.push_back(static_cast<std::uint32_t>(index));
    msg.alternations.push_back(a);
  }
  for (const auto& entry : status.legend) {
    vicc_msgs::CategoryLegend legend;
    legend.id = entry.id;
    legend.label = entry.label;
    legend.hue_name = entry.hue_name;
    legend.color = toMessage(entry.color);
    legend.visible = entry.visible;
    legend.count = static_cast<std::uint32_t>(entry.count);
    msg.legend.push_back(legend);
  }
  msg.hidden_categories = status.hidden_categories;
  msg.notes = status.notes;
  return msg;
}

vicc_msgs::PatientSummary toMessage(const PatientSummary& summary) {
  vicc_msgs::PatientSummary msg;
  msg.patient_id = summary.patient_id;
  msg.examination_count = static_cast<std::uint32_t>(summary.examination_count);
  if (summary.examination_count > 0) {
    msg.first_examination = formatTimestamp(summary.first_examination);
    msg.last_examination = formatTimestamp(summary.last_examination);
  }
  return msg;
}

Examination examinationFromRequest(const EncodingModel& model, const std::string& patient_id,
                                   const std::string& taken_at,
                                   const std::vector<vicc_msgs::Finding>& findings) {
  std::vector<std::string> problems;
  Examination examination;
  examination.patient_id = patient_id;
  examination.source = "service";
  std::string why;
  const auto time = parseTime(taken_at, &why);
  if (!time) {
    problems.push_back("taken_at '" + taken_at + "' is not an ISO 8601 date or date-time: " + why);
  } else {
    examination.taken_at_us = time->us;
  }
  for (std::size_t i = 0; i < findings.size(); ++i) {
    const auto& msg = findings[i];
    Finding finding;
    finding.category = msg.category;
    finding.structure = msg.structure_id;
    const auto side = sideFromString(msg.side);
    if (!side) {
      problems.push_back("finding " + std::to_string(i + 1) + ": side '" + msg.side +
                         "' is not left, right or none");
    } else {
      finding.side = *side;
    }
    for (const auto& value : msg.values) {
      if (finding.values.count(value.prop_type)) {
        problems.push_back("finding " + std::to_string(i + 1) + ": property '" + value.prop_type +
                           "' given twice");
      }
      finding.values[value.prop_type] =
          valueFromText(model, msg.category, value.prop_type, value.value);
    }
    examination.findings.push_back(finding);
  }
  if (!problems.empty()) throw ValidationError(problems);
  return examination;
}

}  // namespace vicc_anatomy_viz::ros_adapter
