#include "vicc_glyphs/perception/perception_model_yaml.hpp"

#include <yaml-cpp/yaml.h>

#include <fstream>
#include <set>
#include <sstream>

namespace vicc_glyphs::perception {
namespace {

// Reads one YAML map, naming every key by its full path in errors and rejecting unknown keys
// (a misspelt key would otherwise silently fall back to a default).
class MapReader {
 public:
  MapReader(const YAML::Node& node, std::string path, std::set<std::string> allowed)
      : node_(node), path_(std::move(path)) {
    if (!node_.IsMap()) throw ModelFileError(where() + " must be a map");
    std::set<std::string> seen;
    for (const auto& entry : node_) {
      const std::string key = entry.first.as<std::string>();
      if (!allowed.count(key)) throw ModelFileError("unknown key " + child(key));
      // yaml-cpp keeps the first of repeated keys: the second would be silently ignored.
      if (!seen.insert(key).second) throw ModelFileError("key " + child(key) + " is given twice");
    }
  }

  std::string child(const std::string& key) const {
    return path_.empty() ? key : path_ + "." + key;
  }
  bool has(const std::string& key) const { return static_cast<bool>(node_[key]); }
  YAML::Node node(const std::string& key) const {
    if (!has(key)) throw ModelFileError("missing key " + child(key));
    return node_[key];
  }

  double number(const std::string& key) const { return scalar<double>(key, "a number"); }
  double number(const std::string& key, double fallback) const {
    return has(key) ? number(key) : fallback;
  }
  bool flag(const std::string& key, bool fallback) const {
    return has(key) ? scalar<bool>(key, "true or false") : fallback;
  }
  int integer(const std::string& key) const { return scalar<int>(key, "an integer"); }

  /// A two-element sequence of numbers.
  std::pair<double, double> pair(const std::string& key) const {
    const YAML::Node value = node(key);
    if (!value.IsSequence() || value.size() != 2) {
      throw ModelFileError(child(key) + " must be a list of two numbers");
    }
    try {
      return {value[0].as<double>(), value[1].as<double>()};
    } catch (const YAML::Exception&) {
      throw ModelFileError(child(key) + " must be a list of two numbers");
    }
  }

 private:
  std::string where() const { return path_.empty() ? "the model file" : path_; }

  template <typename T>
  T scalar(const std::string& key, const char* what) const {
    const YAML::Node value = node(key);
    try {
      if (!value.IsScalar()) throw YAML::Exception(YAML::Mark(), "");
      return value.as<T>();
    } catch (const YAML::Exception&) {
      throw ModelFileError(child(key) + " must be " + what);
    }
  }

  YAML::Node node_;
  std::string path_;
};

std::map<Waveform, WaveformCalibration> readCalibrations(const YAML::Node& node,
                                                         const std::string& path) {
  std::map<Waveform, WaveformCalibration> calibrations;
  const MapReader reader(node, path, {"sine", "triangle", "sawtooth", "rectangle"});
  for (const auto& entry : node) {
    const std::string name = entry.first.as<std::string>();
    const MapReader h(entry.second, reader.child(name), {"k", "l"});
    calibrations[*waveformFromString(name)] = {h.number("k"), h.number("l")};
  }
  return calibrations;
}

// Returns the variable's model and its expected level count (0 when not given).
std::pair<VariableModel, int> readVariable(const YAML::Node& node, const std::string& path) {
  const MapReader reader(node, path,
                         {"stimulus", "stevens", "quantization_step", "scales_with_size",
                          "expected_levels", "waveform_calibration"});
  VariableModel model;
  const MapReader stimulus(reader.node("stimulus"), reader.child("stimulus"), {"adu", "value"});
  std::tie(model.scale.adu_min, model.scale.adu_max) = stimulus.pair("adu");
  std::tie(model.scale.value_at_min, model.scale.value_at_max) = stimulus.pair("value");
  const MapReader stevens(reader.node("stevens"), reader.child("stevens"), {"a", "b", "c"});
  model.stevens = {stevens.number("a"), stevens.number("b"), stevens.number("c")};
  model.quantization_step = reader.number("quantization_step");
  model.scales_with_size = reader.flag("scales_with_size", true);
  if (reader.has("waveform_calibration")) {
    model.calibrations =
        readCalibrations(reader.node("waveform_calibration"), reader.child("waveform_calibration"));
  }
  return {model, reader.has("expected_levels") ? reader.integer("expected_levels") : 0};
}

PerceptionModel readModel(const YAML::Node& root) {
  const MapReader reader(root, "", {"reference_size_mm", "size_transfer", "variables"});
  PerceptionModel model;
  model.reference_size_mm = reader.number("reference_size_mm");
  if (reader.has("size_transfer")) {
    const MapReader transfer(reader.node("size_transfer"), "size_transfer",
                             {"min_scale", "epsilon"});
    model.size_transfer.min_scale = transfer.number("min_scale", 1.0);
    model.size_transfer.epsilon = transfer.number("epsilon", 0.0);
  }
  const YAML::Node variables = reader.node("variables");
  const MapReader list(
      variables, "variables",
      {"geometric_amplitude", "geometric_frequency", "colour_amplitude", "colour_frequency"});
  std::map<VisualVariable, int> expected;
  for (const auto& entry : variables) {
    const std::string name = entry.first.as<std::string>();
    const VisualVariable which = *visualVariableFromString(name);
    std::tie(model.variables[which], expected[which]) =
        readVariable(entry.second, list.child(name));
  }
  if (const std::string problem = model.problem(); !problem.empty()) throw ModelFileError(problem);
  for (const auto& [which, count] : expected) {
    if (count == 0) continue;
    const int derived = model.levelCount(which, model.reference_size_mm);
    if (derived != count) {
      throw ModelFileError("variables." + toString(which) + ".expected_levels is " +
                           std::to_string(count) + " but e, its stimulus range and dv give " +
                           std::to_string(derived) + " levels");
    }
  }
  return model;
}

void emitVariable(YAML::Emitter& out, VisualVariable which, const VariableModel& model,
                  int levels) {
  out << YAML::Key << toString(which) << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "stimulus" << YAML::Value << YAML::Flow << YAML::BeginMap;
  out << YAML::Key << "adu" << YAML::Value << YAML::Flow << YAML::BeginSeq << model.scale.adu_min
      << model.scale.adu_max << YAML::EndSeq;
  out << YAML::Key << "value" << YAML::Value << YAML::Flow << YAML::BeginSeq
      << model.scale.value_at_min << model.scale.value_at_max << YAML::EndSeq << YAML::EndMap;
  out << YAML::Key << "stevens" << YAML::Value << YAML::Flow << YAML::BeginMap;
  out << YAML::Key << "a" << YAML::Value << model.stevens.a << YAML::Key << "b" << YAML::Value
      << model.stevens.b << YAML::Key << "c" << YAML::Value << model.stevens.c << YAML::EndMap;
  out << YAML::Key << "quantization_step" << YAML::Value << model.quantization_step;
  out << YAML::Key << "scales_with_size" << YAML::Value << model.scales_with_size;
  out << YAML::Key << "expected_levels" << YAML::Value << levels;
  if (!model.calibrations.empty()) {
    out << YAML::Key << "waveform_calibration" << YAML::Value << YAML::BeginMap;
    for (const auto& [waveform, h] : model.calibrations) {
      out << YAML::Key << toString(waveform) << YAML::Value << YAML::Flow << YAML::BeginMap
          << YAML::Key << "k" << YAML::Value << h.k << YAML::Key << "l" << YAML::Value << h.l
          << YAML::EndMap;
    }
    out << YAML::EndMap;
  }
  out << YAML::EndMap;
}

}  // namespace

PerceptionModel parsePerceptionModel(const std::string& yaml_text) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    throw ModelFileError(std::string("not valid YAML: ") + e.what());
  }
  return readModel(root);
}

PerceptionModel loadPerceptionModel(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw ModelFileError("cannot read perception model file " + path);
  std::ostringstream text;
  text << file.rdbuf();
  try {
    return parsePerceptionModel(text.str());
  } catch (const ModelFileError& e) {
    throw ModelFileError(path + ": " + e.what());
  }
}

std::string perceptionModelToYaml(const PerceptionModel& model, const std::string& header) {
  YAML::Emitter out;
  out.SetDoublePrecision(7);
  out << YAML::BeginMap;
  out << YAML::Key << "reference_size_mm" << YAML::Value << model.reference_size_mm;
  out << YAML::Key << "size_transfer" << YAML::Value << YAML::BeginMap << YAML::Key << "min_scale"
      << YAML::Value << model.size_transfer.min_scale << YAML::Key << "epsilon" << YAML::Value
      << model.size_transfer.epsilon << YAML::EndMap;
  out << YAML::Key << "variables" << YAML::Value << YAML::BeginMap;
  for (const auto& [which, variable] : model.variables) {
    emitVariable(out, which, variable, model.levelCount(which, model.reference_size_mm));
  }
  out << YAML::EndMap << YAML::EndMap;
  std::ostringstream text;
  std::istringstream lines(header);
  for (std::string line; std::getline(lines, line);) text << "# " << line << "\n";
  text << out.c_str() << "\n";
  return text.str();
}

void savePerceptionModel(const PerceptionModel& model, const std::string& path,
                         const std::string& header) {
  std::ofstream file(path);
  file << perceptionModelToYaml(model, header);
  if (!file) throw std::runtime_error("cannot write perception model file " + path);
}

}  // namespace vicc_glyphs::perception
