#include "levels_command.hpp"

#include <iomanip>
#include <stdexcept>

#include "command_line.hpp"
#include "model_path.hpp"
#include "vicc_glyphs/perception/perception_model_yaml.hpp"

namespace vicc_glyphs::tools {
namespace {

using namespace vicc_glyphs::perception;

const std::vector<OptionSpec>& levelsOptions() {
  static const std::vector<OptionSpec> specs{
      {"size-mm", "MM", "glyph width in mm (default: the model's reference size, 50)"},
      perceptionModelOption(),
      {"waveform", "NAME", "sine (default), triangle, sawtooth or rectangle: calibrated stimuli"},
      {"help", "", "show this help"},
  };
  return specs;
}

void printUsage(std::ostream& out) {
  out << "usage: vicc_glyph levels [--size-mm MM] [--model MODEL.yaml] [--waveform NAME]\n\n"
         "Prints, per visual variable, the perceptually equidistant levels (thesis 6.1) and the\n"
         "stimulus of each for a glyph MM millimetres wide.\n\n"
      << formatOptions(levelsOptions());
}

std::string stimulusHeader(VisualVariable which) {
  if (which == VisualVariable::GeometricAmplitude) return "amplitude[mm]";
  if (which == VisualVariable::ColourAmplitude) return "V";
  return which == VisualVariable::GeometricFrequency ? "period[mm]  waves/10mm"
                                                     : "period[mm]  periods/10mm";
}

void printVariable(const PerceptionModel& model, VisualVariable which, double size_mm,
                   Waveform waveform, std::ostream& out) {
  const VariableModel& variable = model.variable(which);
  const VariableLevels levels = model.levels(which, size_mm, waveform);
  out << std::fixed << std::setprecision(3) << toString(which) << ": " << levels.levels.size()
      << " levels, dv " << variable.quantization_step << " adu, usable range " << levels.range_low
      << " .. " << levels.range_high << " " << stimulusUnit(which) << "\n"
      << "  level  perceived[adu]  stimulus[adu]  " << stimulusHeader(which) << "\n";
  for (const StimulusLevel& level : levels.levels) {
    out << "  " << std::setw(5) << level.index << "  " << std::setw(14) << level.perceived_adu
        << "  " << std::setw(13) << level.stimulus_adu << "  " << std::setw(10) << level.stimulus;
    if (isFrequency(which)) out << "  " << std::setw(10) << level.per10mm();
    out << "\n";
  }
}

}  // namespace

int runLevelsCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  std::string model_path;  // empty: the default model, found below
  double size_mm = 0.0;
  Waveform waveform = Waveform::Sine;
  const auto read = [&](const ParsedArguments& parsed) {
    if (!parsed.positional.empty())
      throw UsageError("unexpected argument '" + parsed.positional[0] + "'");
    if (parsed.has("size-mm")) size_mm = parseNumber("size-mm", parsed.value("size-mm"), 1e-3, 1e4);
    if (parsed.has("model")) model_path = parsed.value("model");
    if (parsed.has("waveform")) {
      const auto named = waveformFromString(parsed.value("waveform"));
      if (!named) throw UsageError("unknown --waveform '" + parsed.value("waveform") + "'");
      waveform = *named;
    }
  };
  const std::optional<int> done =
      readCommandLine("levels", args, levelsOptions(), printUsage, out, err, read);
  if (done) return *done;
  try {
    const PerceptionModel model = loadPerceptionModel(perceptionModelPathOrDefault(model_path));
    if (size_mm == 0.0) size_mm = model.reference_size_mm;
    out << std::fixed << std::setprecision(3) << "glyph size " << size_mm << " mm (scale "
        << size_mm / model.reference_size_mm << " of the " << model.reference_size_mm
        << " mm reference), waveform " << toString(waveform) << ", model " << model_path << "\n\n";
    for (const auto& entry : model.variables) {
      try {
        printVariable(model, entry.first, size_mm, waveform, out);
      } catch (const std::domain_error& e) {
        out << e.what() << "\n";  // this variable cannot encode data at this size
      }
      out << "\n";
    }
  } catch (const std::exception& e) {
    err << "vicc_glyph levels: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace vicc_glyphs::tools
