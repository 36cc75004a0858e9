#pragma once
// The visual encoding engine (thesis 4.3.2.3): an examination's findings -> per structure
// instance the colour (hue = category, saturation-brightness = intensity level), texture and
// its level parameters, proxy flag and overlay text; plus the alternations where several
// categories meet on one structure (spatial non-injectivity, resolved as in 4.3.3).

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "vicc_anatomy_viz/encoding_model.hpp"
#include "vicc_anatomy_viz/examination_validator.hpp"
#include "vicc_anatomy_viz/patient_record.hpp"
#include "vicc_anatomy_viz/visual_variables.hpp"

namespace vicc_anatomy_viz {

struct EncodedProperty {
  std::string prop_type;
  std::string label;
  std::string value;          ///< raw recorded value
  std::string derived_value;  ///< derived from the raw one, "" if not derived
  std::string visual_variable;
  int level = 0;
  int level_count = 0;
  bool normal = false;
};

struct EncodedStructure {
  std::string structure_id;
  Side side = Side::kNone;
  std::string structure_class;
  std::string display_name;
  std::string fma_id;
  std::string category;
  Rgba color;
  double hue_deg = 0.0, saturation = 0.0, brightness = 0.0;
  int intensity_level = 0, intensity_levels = 0;
  std::string texture_id;
  int texture_level = 0, texture_levels = 0;
  double texture_frequency = 0.0, texture_amplitude = 0.0;
  bool proxy = false;
  std::string overlay_text;
  std::vector<EncodedProperty> properties;
  int alternation_group = -1;
};

struct Alternation {
  std::string structure_id;
  Side side = Side::kNone;
  std::string display_name;
  std::vector<std::string> categories;  ///< view order; the first is shown by default
  std::vector<std::size_t> entries;     ///< indices into EncodedStatus::structures
};

struct LegendEntry {
  std::string id;
  std::string label;
  std::string hue_name;
  Rgba color;
  bool visible = true;
  std::size_t count = 0;
};

struct EncodedStatus {
  std::string patient_id;
  std::string view_id;
  std::string requested_date;
  bool has_examination = false;
  TimestampUs examination_time = 0;
  ExaminationStatus examination_status = ExaminationStatus::kFinal;
  bool partial = false;  ///< missing findings are unknown, not normal
  std::string partial_reason;
  std::vector<EncodedStructure> structures;
  std::vector<Alternation> alternations;
  std::vector<LegendEntry> legend;
  std::vector<std::string> hidden_categories;
  std::vector<std::string> notes;
};

struct EncodeOptions {
  std::string requested_date;                  ///< echoed in the output
  std::vector<std::string> hidden_categories;  ///< the category filter
};

class StatusEncoder {
 public:
  /// Throws ConfigError when the view is unknown.
  StatusEncoder(const EncodingModel& model, const std::string& view_id);

  /// Encodes a (validated) examination; nullopt encodes "no examination at that date".
  /// Throws ValidationError for a hidden category that is not part of the view.
  EncodedStatus encode(const std::string& patient_id, const std::optional<Examination>& examination,
                       const EncodeOptions& options = {}) const;

 private:
  bool displayed(const Finding& finding, const Examination& examination) const;
  EncodedStructure encodeFinding(const Finding& finding) const;
  std::vector<const Finding*> usableFindings(const Examination& examination,
                                             std::vector<std::string>& notes) const;
  /// Findings of the view's categories that usableFindings() had to leave out.
  std::size_t unusableCount(const Examination& examination, std::size_t usable) const;
  std::vector<LegendEntry> legend(const std::map<std::string, std::size_t>& counts,
                                  const std::vector<std::string>& hidden) const;

  const EncodingModel& model_;
  const View& view_;
  ExaminationValidator validator_;  ///< screens records written under an older configuration
};

}  // namespace vicc_anatomy_viz
