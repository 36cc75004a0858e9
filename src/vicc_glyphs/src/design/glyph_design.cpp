#include "vicc_glyphs/design/glyph_design.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "design_yaml.hpp"

namespace vicc_glyphs::design {
namespace {

using perception::PerceptionModel;
using perception::VisualVariable;

const std::map<std::string, Channel>& channelNames() {
  static const std::map<std::string, Channel> names{
      {"geometric_frequency", Channel::GeometricFrequency},
      {"geometric_amplitude", Channel::GeometricAmplitude},
      {"colour_frequency", Channel::ColourFrequency},
      {"colour_amplitude", Channel::ColourAmplitude},
      {"inflate", Channel::Inflate},
      {"fill_color", Channel::FillColor},
      {"glyph_scale", Channel::GlyphScale},
      {"hide", Channel::Hide},
      {"band", Channel::Band},
      {"centre_dashes", Channel::CentreDashes},
  };
  return names;
}

std::optional<VisualVariable> modelVariable(Channel channel) {
  if (channel == Channel::GeometricFrequency) return VisualVariable::GeometricFrequency;
  if (channel == Channel::GeometricAmplitude) return VisualVariable::GeometricAmplitude;
  if (channel == Channel::ColourFrequency) return VisualVariable::ColourFrequency;
  if (channel == Channel::ColourAmplitude) return VisualVariable::ColourAmplitude;
  return std::nullopt;
}

void requireCount(size_t count, int levels, const std::string& key) {
  if (static_cast<int>(count) != levels) {
    throw DesignError(key + " needs one entry per data level (" + std::to_string(levels) +
                      "), got " + std::to_string(count));
  }
}

void readModelLevels(const YamlMap& map, Encoding& encoding, VisualVariable variable, int levels,
                     double size_mm, const PerceptionModel& model) {
  encoding.model_levels = map.integers("levels");
  requireCount(encoding.model_levels.size(), levels, map.key("levels"));
  int available = 0;
  try {
    available = model.levelCount(variable, size_mm);
  } catch (const std::exception& e) {
    throw DesignError(map.key("levels") + ": " + e.what());
  }
  for (int level : encoding.model_levels) {
    if (level < -1 || level >= available) {
      throw DesignError(map.key("levels") + ": level " + std::to_string(level) + " of " +
                        perception::toString(variable) + " does not exist at " +
                        std::to_string(size_mm) + " mm (" + std::to_string(available) + " levels)");
    }
  }
}

// The fixed amplitude of a geometric_frequency encoding: waves flatter than the model's
// smallest geometric amplitude at the glyph's size show no frequency, so that every level
// would look the same.
void requirePerceptibleAmplitude(const YamlMap& map, double amplitude_mm, double size_mm,
                                 const PerceptionModel& model) {
  double smallest = 0.0;
  try {
    smallest = model.levels(VisualVariable::GeometricAmplitude, size_mm).range_low;
  } catch (const std::exception& e) {
    throw DesignError(map.key("amplitude_mm") + ": " + e.what());
  }
  if (!(amplitude_mm >= smallest * (1.0 - 1e-9))) {
    std::ostringstream message;
    message << map.key("amplitude_mm") << " = " << amplitude_mm
            << " mm is below the smallest perceptible geometric amplitude of a " << size_mm
            << " mm glyph, " << smallest << " mm: the waves would show no frequency";
    throw DesignError(message.str());
  }
}

void readHidden(const YamlMap& map, Encoding& encoding, int levels) {
  const YAML::Node hidden = map.node("hidden");
  if (!hidden.IsSequence()) throw DesignError(map.key("hidden") + " must be a list of lists");
  requireCount(hidden.size(), levels, map.key("hidden"));
  for (size_t i = 0; i < hidden.size(); ++i) {
    try {
      encoding.hidden.push_back(hidden[i].as<std::vector<int>>());
    } catch (const YAML::Exception&) {
      throw DesignError(map.key("hidden") + "[" + std::to_string(i) +
                        "] must be a list of curve indices");
    }
  }
}

void readBand(const YamlMap& map, Encoding& encoding, int levels) {
  encoding.band_mm = map.number("band_mm");
  if (!(encoding.band_mm > 0.0)) throw DesignError(map.key("band_mm") + " must be > 0");
  encoding.value_factors = map.numbers("value_factors");
  encoding.saturation_factors = map.numbers("saturation_factors");
  requireCount(encoding.value_factors.size(), levels, map.key("value_factors"));
  requireCount(encoding.saturation_factors.size(), levels, map.key("saturation_factors"));
  for (size_t i = 0; i < encoding.value_factors.size(); ++i) {
    if (!(encoding.value_factors[i] > 0.0) || !(encoding.saturation_factors[i] >= 0.0)) {
      throw DesignError(map.key("value_factors") + " must be > 0, saturation_factors >= 0");
    }
  }
}

void readCentreDashes(const YamlMap& map, Encoding& encoding, int levels) {
  encoding.inset_mm = map.number("inset_mm");
  if (!(encoding.inset_mm > 0.0)) throw DesignError(map.key("inset_mm") + " must be > 0");
  encoding.dash_counts = map.integers("dash_counts");
  requireCount(encoding.dash_counts.size(), levels, map.key("dash_counts"));
  for (int count : encoding.dash_counts) {
    if (count < 0) throw DesignError(map.key("dash_counts") + " must be >= 0");
  }
  encoding.colors = map.colors("colors");
  requireCount(encoding.colors.size(), levels, map.key("colors"));
}

Encoding readEncoding(const YAML::Node& node, const std::string& path, int levels, double size_mm,
                      const PerceptionModel& model) {
  const YamlMap map(node, path,
                    {"channel", "curves", "levels", "waveform", "amplitude_mm", "waves_per_10mm",
                     "dash_color", "offsets_mm", "factors", "colors", "replace", "hidden",
                     "band_mm", "value_factors", "saturation_factors", "inset_mm", "dash_counts"});
  Encoding encoding;
  const std::string channel = map.text("channel");
  const auto found = channelNames().find(channel);
  if (found == channelNames().end()) {
    throw DesignError(map.key("channel") + ": unknown channel '" + channel + "'");
  }
  encoding.channel = found->second;
  try {
    encoding.curves = pacemod::CurveSelection::parse(map.text("curves", "all"));
  } catch (const std::invalid_argument& e) {
    throw DesignError(map.key("curves") + ": " + e.what());
  }
  if (const auto variable = modelVariable(encoding.channel)) {
    readModelLevels(map, encoding, *variable, levels, size_mm, model);
  }
  const std::string waveform = map.text("waveform", "sine");
  const auto parsed = perception::waveformFromString(waveform);
  if (!parsed) throw DesignError(map.key("waveform") + ": unknown waveform '" + waveform + "'");
  encoding.waveform = *parsed;
  encoding.amplitude_mm = map.number("amplitude_mm", encoding.amplitude_mm);
  encoding.waves_per_10mm = map.number("waves_per_10mm", encoding.waves_per_10mm);
  if (!(encoding.amplitude_mm >= 0.0)) throw DesignError(map.key("amplitude_mm") + " must be >= 0");
  if (encoding.channel == Channel::GeometricFrequency) {
    requirePerceptibleAmplitude(map, encoding.amplitude_mm, size_mm, model);
  }
  if (!(encoding.waves_per_10mm > 0.0))
    throw DesignError(map.key("waves_per_10mm") + " must be > 0");
  if (map.has("dash_color")) encoding.dash_color = map.color("dash_color");
  switch (encoding.channel) {
    case Channel::Inflate:
      encoding.numbers = map.numbers("offsets_mm");
      requireCount(encoding.numbers.size(), levels, map.key("offsets_mm"));
      break;
    case Channel::GlyphScale:
      encoding.numbers = map.numbers("factors");
      requireCount(encoding.numbers.size(), levels, map.key("factors"));
      for (double f : encoding.numbers) {
        if (!(f > 0.0)) throw DesignError(map.key("factors") + " must be > 0");
      }
      break;
    case Channel::FillColor:
      encoding.colors = map.colors("colors");
      requireCount(encoding.colors.size(), levels, map.key("colors"));
      encoding.replace = map.color("replace");
      break;
    case Channel::Hide:
      readHidden(map, encoding, levels);
      break;
    case Channel::Band:
      readBand(map, encoding, levels);
      break;
    case Channel::CentreDashes:
      readCentreDashes(map, encoding, levels);
      break;
    default:
      break;
  }
  return encoding;
}

// edges_belong_below: one bool for all edges or a list with one per edge (default false).
std::vector<bool> readEdgeSides(const YamlMap& map, size_t edges) {
  if (!map.has("edges_belong_below")) return std::vector<bool>(edges, false);
  const YAML::Node node = map.node("edges_belong_below");
  const std::string key = map.key("edges_belong_below");
  try {
    if (node.IsScalar()) return std::vector<bool>(edges, node.as<bool>());
    if (node.IsSequence() && node.size() == edges) {
      std::vector<bool> sides;
      for (size_t i = 0; i < edges; ++i) sides.push_back(node[i].as<bool>());
      return sides;
    }
  } catch (const YAML::Exception&) {
  }
  throw DesignError(key + " must be true/false or a list of one per edge");
}

DesignVariable readVariable(const YAML::Node& node, const std::string& path, double size_mm,
                            const PerceptionModel& model) {
  const YamlMap map(node, path,
                    {"name", "unit", "domain", "edges", "edges_belong_below", "encodings"});
  DesignVariable variable;
  variable.name = map.text("name");
  const std::vector<double> domain = map.numbers("domain");
  if (domain.size() != 2 || !(domain[0] < domain[1])) {
    throw DesignError(map.key("domain") + " must be [lower, upper] with lower < upper");
  }
  variable.lower = domain[0], variable.upper = domain[1];
  variable.edges = map.has("edges") ? map.numbers("edges") : std::vector<double>{};
  for (size_t i = 0; i < variable.edges.size(); ++i) {
    const double edge = variable.edges[i];
    if (!(edge > variable.lower && edge < variable.upper) ||
        (i > 0 && !(edge > variable.edges[i - 1]))) {
      throw DesignError(map.key("edges") + " must increase strictly inside the domain");
    }
  }
  variable.edge_belongs_below = readEdgeSides(map, variable.edges.size());
  const YAML::Node encodings = map.node("encodings");
  if (!encodings.IsSequence() || encodings.size() == 0) {
    throw DesignError(map.key("encodings") + " must be a non-empty list");
  }
  for (size_t i = 0; i < encodings.size(); ++i) {
    variable.encodings.push_back(readEncoding(encodings[i],
                                              map.key("encodings") + "[" + std::to_string(i) + "]",
                                              variable.levelCount(), size_mm, model));
  }
  return variable;
}

GlyphDesign readDesign(const YAML::Node& root, const std::string& base_dir,
                       const PerceptionModel& model) {
  const YamlMap map(
      root, "", {"name", "description", "icon", "size_mm", "size_px", "background", "variables"});
  GlyphDesign design;
  design.name = map.text("name");
  design.description = map.text("description", "");
  const std::filesystem::path icon = map.text("icon");
  design.icon_path = (icon.is_absolute() ? icon : std::filesystem::path(base_dir) / icon).string();
  design.size_mm = map.number("size_mm", design.size_mm);
  if (!(design.size_mm > 0.0)) throw DesignError("size_mm must be > 0");
  design.size_px = map.integer("size_px", design.size_px);
  if (design.size_px < kMinGlyphPixels || design.size_px > kMaxGlyphPixels) {
    throw DesignError("size_px must be " + std::to_string(kMinGlyphPixels) + ".." +
                      std::to_string(kMaxGlyphPixels));
  }
  if (map.has("background")) design.background = map.color("background");
  const YAML::Node variables = map.node("variables");
  if (!variables.IsSequence() || variables.size() == 0) {
    throw DesignError("variables must be a non-empty list");
  }
  for (size_t i = 0; i < variables.size(); ++i) {
    design.variables.push_back(
        readVariable(variables[i], "variables[" + std::to_string(i) + "]", design.size_mm, model));
    for (size_t j = 0; j < i; ++j) {
      if (design.variables[j].name == design.variables[i].name) {
        throw DesignError("variables[" + std::to_string(i) + "]: duplicate name '" +
                          design.variables[i].name + "'");
      }
    }
  }
  return design;
}

int levelOf(const DesignVariable& variable, double value) {
  int level = 0;
  for (size_t i = 0; i < variable.edges.size(); ++i) {
    const double edge = variable.edges[i];
    if (variable.edge_belongs_below[i] ? value > edge : value >= edge) ++level;
  }
  return level;
}

}  // namespace

std::vector<int> GlyphDesign::levelsFor(const std::map<std::string, double>& values) const {
  for (const auto& [name, value] : values) {
    bool known = false;
    for (const DesignVariable& v : variables) known = known || v.name == name;
    if (!known) throw DesignValueError("design " + this->name + " has no variable '" + name + "'");
  }
  std::vector<int> levels;
  for (const DesignVariable& variable : variables) {
    const auto found = values.find(variable.name);
    if (found == values.end()) throw DesignValueError("missing value for '" + variable.name + "'");
    const double value = found->second;
    if (std::isnan(value)) throw DesignValueError(variable.name + " is NaN");
    if (value < variable.lower || value > variable.upper) {
      std::ostringstream text;  // enough digits that a value just outside does not print inside
      text << std::setprecision(15) << variable.name << " = " << value << " is outside its domain ["
           << variable.lower << ", " << variable.upper << "]";
      throw DesignValueError(text.str());
    }
    levels.push_back(levelOf(variable, value));
  }
  return levels;
}

GlyphDesign parseDesign(const std::string& yaml_text, const std::string& base_dir,
                        const PerceptionModel& model) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    throw DesignError(std::string("not valid YAML: ") + e.what());
  }
  try {
    return readDesign(root, base_dir, model);
  } catch (const YAML::Exception& e) {
    throw DesignError(std::string("malformed entry: ") + e.what());
  }
}

GlyphDesign loadDesign(const std::string& path, const PerceptionModel& model) {
  std::ifstream file(path);
  if (!file) throw DesignError("cannot read design file " + path);
  std::ostringstream text;
  text << file.rdbuf();
  try {
    return parseDesign(text.str(), std::filesystem::path(path).parent_path().string(), model);
  } catch (const DesignError& e) {
    throw DesignError(path + ": " + e.what());
  }
}

}  // namespace vicc_glyphs::design
