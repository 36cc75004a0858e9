#include "vicc_glyphs/perception/visual_variable.hpp"

#include <utility>

namespace vicc_glyphs::perception {
namespace {

const std::array<std::pair<VisualVariable, const char*>, 4> kVariableNames{{
    {VisualVariable::GeometricAmplitude, "geometric_amplitude"},
    {VisualVariable::GeometricFrequency, "geometric_frequency"},
    {VisualVariable::ColourAmplitude, "colour_amplitude"},
    {VisualVariable::ColourFrequency, "colour_frequency"},
}};

const std::array<std::pair<Waveform, const char*>, 4> kWaveformNames{{
    {Waveform::Sine, "sine"},
    {Waveform::Triangle, "triangle"},
    {Waveform::Sawtooth, "sawtooth"},
    {Waveform::Rectangle, "rectangle"},
}};

template <typename Enum, size_t N>
std::string nameOf(const std::array<std::pair<Enum, const char*>, N>& names, Enum value) {
  for (const auto& [entry, name] : names) {
    if (entry == value) return name;
  }
  return "unknown";
}

template <typename Enum, size_t N>
std::optional<Enum> valueOf(const std::array<std::pair<Enum, const char*>, N>& names,
                            const std::string& text) {
  for (const auto& [entry, name] : names) {
    if (text == name) return entry;
  }
  return std::nullopt;
}

}  // namespace

std::string toString(VisualVariable variable) { return nameOf(kVariableNames, variable); }

std::optional<VisualVariable> visualVariableFromString(const std::string& name) {
  return valueOf(kVariableNames, name);
}

std::string stimulusUnit(VisualVariable variable) {
  if (variable == VisualVariable::ColourAmplitude) return "V";
  return isFrequency(variable) ? "mm period" : "mm";
}

bool isFrequency(VisualVariable variable) {
  return variable == VisualVariable::GeometricFrequency ||
         variable == VisualVariable::ColourFrequency;
}

std::string toString(Waveform waveform) { return nameOf(kWaveformNames, waveform); }

std::optional<Waveform> waveformFromString(const std::string& name) {
  return valueOf(kWaveformNames, name);
}

}  // namespace vicc_glyphs::perception
