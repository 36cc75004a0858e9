#pragma once
// Which value of an examination a status glyph shows (e.g. the intracranial pressure above the
// avatar's head), and what it shows when there is none. ROS- and Qt-free.
//
// A measured category such as ICP is not examined by default: an examination without its
// finding, or with the finding but without the value, has NO value -- never the normal one the
// data model assumes for an omitted finding or property.

#include <optional>
#include <string>

#include "vicc_anatomy_viz/encoding_model.hpp"
#include "vicc_anatomy_viz/patient_record.hpp"

namespace vicc_anatomy_viz::status_glyph {

/// A category's numerical property feeding a glyph design's variables.
struct GlyphBinding {
  std::string category = "intracranial_pressure";
  std::string property = "intensity";
  std::string design = "intracranial_pressure";  ///< vicc_glyphs design name
  std::string value_variable = "pressure";       ///< design variable given the recorded value
  std::string level_variable = "category";       ///< ... given the level (0 = normal value)

  /// Throws ConfigError naming the parameter when the category or property is not in the
  /// view, the property is not numerical, or a design/variable name is empty.
  void validate(const EncodingModel& model, const std::string& view_id) const;
};

enum class ReadingKind {
  kNoExamination,  ///< nothing recorded at or before the date: no glyph, no caption
  kHidden,         ///< the category is filtered out in the panel: nothing drawn
  kNoData,         ///< an examination without the value: "no data", never a glyph
  kValue,          ///< a recorded value: the glyph
};

struct GlyphReading {
  ReadingKind kind = ReadingKind::kNoExamination;
  int value = 0;        ///< the recorded value (kValue)
  int level = 0;        ///< its level: 0 the normal value, 1..level_count above (kValue)
  int level_count = 0;  ///< levels of the abnormal values
  std::string caption;  ///< e.g. "ICP (mmHg) 26 [level 2/2] 2023-03-06T09:15:00Z"
};

/// The reading of `examination` (nullopt: none at the date).
GlyphReading readGlyph(const EncodingModel& model, const GlyphBinding& binding,
                       const std::optional<Examination>& examination, bool category_hidden);

}  // namespace vicc_anatomy_viz::status_glyph
