#include "vicc_anatomy_viz/status_encoder.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "vicc_anatomy_viz/errors.hpp"

namespace vicc_anatomy_viz {

namespace {

/// A property's value in a finding: recorded, derived from its recorded source, or the
/// normal value assumed when the property was omitted.
struct ResolvedValue {
  Value value;
  std::string raw;  ///< as recorded (the source value for derived properties)
  bool derived = false;
};

ResolvedValue resolve(const Property& prop, const Finding& finding) {
  const auto given = finding.values.find(prop.prop_type);
  if (given != finding.values.end()) return {given->second, given->second.toString(), false};
  if (prop.source) {
    const auto source = finding.values.find(prop.source->prop_type);
    if (source != finding.values.end()) {
      const auto derived = prop.source->derive.find(source->second.toString());
      if (derived != prop.source->derive.end()) {
        return {derived->second, source->second.toString(), true};
      }
    }
  }
  const Value normal = prop.defaultValue().value_or(Value());
  return {normal, normal.toString(), false};
}

std::string describeValue(const Property& prop, const ResolvedValue& resolved) {
  std::ostringstream out;
  out << prop.label << " " << resolved.value.toString();
  if (resolved.derived) {
    out << " (" << prop.source->label << " " << resolved.raw;
    if (prop.source->domain.type == DataType::kNumerical)
      out << " [" << prop.source->domain.describe() << "]";
    out << ")";
  } else if (prop.domain.type == DataType::kNumerical) {
    out << " [" << prop.domain.describe() << "]";
  }
  return out.str();
}

const Finding* findFinding(const Examination& examination, const std::string& category,
                           const std::string& structure, Side side) {
  for (const auto& finding : examination.findings) {
    if (finding.category == category && finding.structure == structure && finding.side == side) {
      return &finding;
    }
  }
  return nullptr;
}

double lerp(double weak, double strong, double t) { return weak + t * (strong - weak); }

}  // namespace

StatusEncoder::StatusEncoder(const EncodingModel& model, const std::string& view_id)
    : model_(model), view_(model.view(view_id)), validator_(model, view_id) {}

bool StatusEncoder::displayed(const Finding& finding, const Examination& examination) const {
  const Category& category = model_.category(finding.category);
  for (const auto& prop : category.props) {
    if (!prop.isNormal(resolve(prop, finding).value)) return true;
  }
  // DG5 hides normal values, but an asymmetric reflex is read by comparing both sides.
  if (!category.compare_contralateral || finding.side == Side::kNone) return false;
  const Finding* other =
      findFinding(examination, finding.category, finding.structure, contralateral(finding.side));
  if (!other) return false;
  for (const auto& prop : category.props) {
    if (resolve(prop, finding).value != resolve(prop, *other).value) return true;
  }
  return false;
}

EncodedStructure StatusEncoder::encodeFinding(const Finding& finding) const {
  const AnatomyCatalog& anatomy = model_.anatomy();
  const Structure& structure = *anatomy.structure(finding.structure);
  const StructureClass& structure_class = anatomy.classOf(structure);
  const Category& category = model_.category(finding.category);

  EncodedStructure out;
  out.structure_id = structure.id;
  out.side = finding.side;
  out.structure_class = structure_class.id;
  out.display_name = anatomy.displayName(structure, finding.side);
  out.fma_id = structure.fma_id;
  out.category = category.id;
  out.proxy = structure_class.proxy;
  out.hue_deg = model_.hueOf(view_, category.id).degrees;
  // Without an intensity property the category is shown at full strength.
  out.saturation = 1.0;
  out.brightness = 1.0;
  double alpha = 1.0;

  std::ostringstream overlay;
  overlay << out.display_name << " \u2014 " << category.label << ":";
  bool first = true;
  for (const auto& prop : category.props) {
    const ResolvedValue resolved = resolve(prop, finding);
    const LevelMapping& levels = model_.levels(category.id, prop.prop_type);
    const VisualVariable& variable = model_.variableOf(prop);
    const int level = levels.levelOf(resolved.value);
    const int level_count = levels.levelCount();
    const double t = VisualVariable::spread(level, level_count);

    EncodedProperty encoded;
    encoded.prop_type = prop.prop_type;
    encoded.label = prop.label;
    encoded.value = resolved.raw;
    encoded.derived_value = resolved.derived ? resolved.value.toString() : "";
    encoded.visual_variable = variable.id;
    encoded.level = level;
    encoded.level_count = level_count;
    encoded.normal = prop.isNormal(resolved.value);
    out.properties.push_back(encoded);

    switch (variable.channel) {
      case Channel::kSaturationBrightness:
        out.intensity_level = level;
        out.intensity_levels = level_count;
        out.saturation = level == 0 ? variable.unindicated_saturation
                                    : lerp(variable.saturation_weak, variable.saturation_strong, t);
        out.brightness = level == 0 ? variable.unindicated_brightness
                                    : lerp(variable.brightness_weak, variable.brightness_strong, t);
        break;
      case Channel::kTexture:
        out.texture_levels = level_count;
        if (level > 0) {
          // Few levels use the most distinct of the texture's frequency/amplitude pairs.
          const int slots = static_cast<int>(variable.texture_levels.size());
          const auto slot = static_cast<std::size_t>(std::lround(t * (slots - 1)));
          out.texture_id = variable.id;
          out.texture_level = level;
          out.texture_frequency = variable.texture_levels[slot].frequency;
          out.texture_amplitude = variable.texture_levels[slot].amplitude;
        }
        break;
      case Channel::kTransparency:
        if (level > 0) alpha = lerp(variable.alpha_weak, variable.alpha_strong, t);
        break;
    }
    overlay << (first ? " " : ", ") << describeValue(prop, resolved);
    first = false;
  }
  out.color = hsvToRgba(out.hue_deg, out.saturation, out.brightness, alpha);
  out.overlay_text = overlay.str();
  return out;
}

namespace {

/// A partial or preliminary examination says so on every structure and in the notes: the
/// overlay is what a clinician reads, and a missing finding of a partial examination is
/// unknown, not normal.
void markIncompleteness(EncodedStatus& status) {
  std::string tag;
  if (status.partial) {
    status.notes.insert(status.notes.begin(),
                        "PARTIAL EXAMINATION (" + status.partial_reason +
                            "): structures without a finding are not known to be normal");
    tag += " [partial examination]";
  }
  if (status.examination_status == ExaminationStatus::kPreliminary) {
    status.notes.insert(status.notes.begin(), "PRELIMINARY examination result");
    tag += " [preliminary]";
  }
  for (auto& entry : status.structures) entry.overlay_text += tag;
}

/// Spatial non-injectivity in one status: several categories on one structure instance are
/// listed as an alternation (the first, in view order, is shown by default).
void markAlternations(EncodedStatus& status) {
  std::map<std::pair<std::string, Side>, std::vector<std::size_t>> by_structure;
  std::vector<std::pair<std::string, Side>> order;
  for (std::size_t i = 0; i < status.structures.size(); ++i) {
    const auto key = std::make_pair(status.structures[i].structure_id, status.structures[i].side);
    if (!by_structure.count(key)) order.push_back(key);
    by_structure[key].push_back(i);
  }
  for (const auto& key : order) {
    const auto& entries = by_structure[key];
    if (entries.size() < 2) continue;
    Alternation alternation;
    alternation.structure_id = key.first;
    alternation.side = key.second;
    alternation.display_name = status.structures[entries.front()].display_name;
    alternation.entries = entries;
    for (const std::size_t index : entries) {
      alternation.categories.push_back(status.structures[index].category);
      status.structures[index].alternation_group = static_cast<int>(status.alternations.size());
    }
    status.alternations.push_back(alternation);
  }
}

bool contains(const std::vector<std::string>& list, const std::string& item) {
  return std::find(list.begin(), list.end(), item) != list.end();
}

}  // namespace

std::size_t StatusEncoder::unusableCount(const Examination& examination, std::size_t usable) const {
  const auto in_view =
      std::count_if(examination.findings.begin(), examination.findings.end(),
                    [&](const Finding& finding) { return view_.contains(finding.category); });
  return static_cast<std::size_t>(in_view) - usable;
}

std::vector<const Finding*> StatusEncoder::usableFindings(const Examination& examination,
                                                          std::vector<std::string>& notes) const {
  // Records are validated when written; one that no longer fits the configuration (changed
  // since) is left out with a note instead of being drawn wrongly.
  std::vector<const Finding*> usable;
  for (const auto& finding : examination.findings) {
    if (!view_.contains(finding.category)) continue;
    const auto problems = validator_.findingProblems(finding);
    if (problems.empty()) {
      usable.push_back(&finding);
    } else {
      notes.push_back("not shown: " + finding.describe() + ": " + problems.front());
    }
  }
  return usable;
}

std::vector<LegendEntry> StatusEncoder::legend(const std::map<std::string, std::size_t>& counts,
                                               const std::vector<std::string>& hidden) const {
  std::vector<LegendEntry> legend;
  for (const auto& entry : view_.categories) {
    const Category& category = model_.category(entry.category);
    const NamedHue& hue = model_.hueOf(view_, entry.category);
    LegendEntry item;
    item.id = category.id;
    item.label = category.label;
    item.hue_name = hue.name;
    double saturation = 1.0, brightness = 1.0;
    for (const auto& prop : category.props) {
      const VisualVariable& variable = model_.variableOf(prop);
      if (variable.channel == Channel::kSaturationBrightness) {
        saturation = variable.saturation_strong;
        brightness = variable.brightness_strong;
      }
    }
    item.color = hsvToRgba(hue.degrees, saturation, brightness);
    item.visible = !contains(hidden, entry.category);
    const auto count = counts.find(entry.category);
    item.count = count == counts.end() ? 0 : count->second;
    legend.push_back(item);
  }
  return legend;
}

EncodedStatus StatusEncoder::encode(const std::string& patient_id,
                                    const std::optional<Examination>& examination,
                                    const EncodeOptions& options) const {
  std::vector<std::string> unknown;
  for (const auto& hidden : options.hidden_categories) {
    if (!view_.contains(hidden)) {
      unknown.push_back("category filter: '" + hidden + "' is not a category of view '" + view_.id +
                        "'");
    }
  }
  if (!unknown.empty()) throw ValidationError(unknown);

  EncodedStatus status;
  status.patient_id = patient_id;
  status.view_id = view_.id;
  status.requested_date = options.requested_date;
  status.hidden_categories = options.hidden_categories;
  status.notes = model_.notes(view_);
  std::map<std::string, std::size_t> counts;  // displayed findings per category, filter aside
  if (examination) {
    status.has_examination = true;
    status.examination_time = examination->taken_at_us;
    status.examination_status = examination->status;
    status.partial = examination->partial;
    status.partial_reason = examination->partial_reason;
    const AnatomyCatalog& anatomy = model_.anatomy();
    const auto usable = usableFindings(*examination, status.notes);
    const std::size_t unusable = unusableCount(*examination, usable.size());
    if (unusable > 0) {
      // Shown without those findings, the status would read as better than recorded.
      status.partial = true;
      status.partial_reason += std::string(status.partial_reason.empty() ? "" : "; ") +
                               std::to_string(unusable) +
                               " recorded finding(s) not shown: they no longer fit the "
                               "configuration";
    }
    for (const auto& entry : view_.categories) {
      std::vector<const Finding*> findings;
      for (const Finding* finding : usable) {
        if (finding->category == entry.category && displayed(*finding, *examination)) {
          findings.push_back(finding);
        }
      }
      std::sort(findings.begin(), findings.end(), [&](const Finding* a, const Finding* b) {
        const int oa = anatomy.order(a->structure), ob = anatomy.order(b->structure);
        return oa != ob ? oa < ob : a->side < b->side;
      });
      counts[entry.category] = findings.size();
      if (contains(options.hidden_categories, entry.category)) continue;
      for (const Finding* finding : findings) status.structures.push_back(encodeFinding(*finding));
    }
    markAlternations(status);
    markIncompleteness(status);
  }
  status.legend = legend(counts, options.hidden_categories);
  return status;
}

}  // namespace vicc_anatomy_viz
