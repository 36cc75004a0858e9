#include "vicc_anatomy_viz/status_glyph/glyph_reading.hpp"

#include <algorithm>

#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/time_format.hpp"

namespace vicc_anatomy_viz::status_glyph {

void GlyphBinding::validate(const EncodingModel& model, const std::string& view_id) const {
  for (const auto& [key, text] : {std::pair<const char*, const std::string&>{"design", design},
                                  {"value_variable", value_variable},
                                  {"level_variable", level_variable}}) {
    if (text.empty()) throw ConfigError(std::string(key) + " is empty");
  }
  const View& view = model.view(view_id);
  if (!view.contains(category)) {
    throw ConfigError("category '" + category + "' is not part of view '" + view_id + "'");
  }
  const Property* prop = model.category(category).property(property);
  if (!prop) {
    throw ConfigError("property '" + property + "' is not a property of category '" + category +
                      "'");
  }
  if (prop->domain.type != DataType::kNumerical || prop->source) {
    throw ConfigError("property '" + category + "." + property +
                      "' must be numerical and recorded directly (no source) to feed a glyph");
  }
}

namespace {

std::string tags(const Examination& examination) {
  std::string out;
  if (examination.partial) out += " [partial examination]";
  if (examination.status == ExaminationStatus::kPreliminary) out += " [preliminary]";
  return out;
}

std::string levelText(int level, int level_count) {
  if (level == 0) return "normal";
  return "level " + std::to_string(level) + "/" + std::to_string(level_count);
}

}  // namespace

GlyphReading readGlyph(const EncodingModel& model, const GlyphBinding& binding,
                       const std::optional<Examination>& examination, bool category_hidden) {
  GlyphReading reading;
  if (!examination) return reading;
  if (category_hidden) {
    reading.kind = ReadingKind::kHidden;
    return reading;
  }
  const Category& category = model.category(binding.category);
  const Property& prop = *category.property(binding.property);
  const std::string when = " " + formatTimestamp(examination->taken_at_us) + tags(*examination);
  const auto finding =
      std::find_if(examination->findings.begin(), examination->findings.end(),
                   [&](const Finding& f) { return f.category == binding.category; });
  const Value* value = nullptr;
  if (finding != examination->findings.end()) {
    const auto it = finding->values.find(binding.property);
    if (it != finding->values.end() && prop.domain.contains(it->second)) value = &it->second;
  }
  // No finding, or a finding that omits the value: unknown, not the normal default.
  if (!value) {
    reading.kind = ReadingKind::kNoData;
    reading.caption = category.label + ": no data" + when;
    return reading;
  }
  const LevelMapping& levels = model.levels(binding.category, binding.property);
  reading.kind = ReadingKind::kValue;
  reading.value = value->asNumber();
  reading.level = levels.levelOf(*value);
  reading.level_count = levels.levelCount();
  reading.caption = prop.label + " " + std::to_string(reading.value) + " (" +
                    levelText(reading.level, reading.level_count) + ")" + when;
  return reading;
}

}  // namespace vicc_anatomy_viz::status_glyph
