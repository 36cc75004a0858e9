#pragma once
// The quantitative visual variables of periodic contour modifications (thesis 6.1) and the
// waveforms of geometric waves.

#include <array>
#include <optional>
#include <string>

namespace vicc_glyphs::perception {

enum class VisualVariable {
  GeometricAmplitude,  ///< wave amplitude in mm
  GeometricFrequency,  ///< wave frequency; its stimulus is the period length in mm
  ColourAmplitude,     ///< value/brightness V (HSV) of the modified intervals
  ColourFrequency,     ///< colour-interval frequency; its stimulus is the period length in mm
};

constexpr std::array<VisualVariable, 4> kAllVisualVariables{
    VisualVariable::GeometricAmplitude, VisualVariable::GeometricFrequency,
    VisualVariable::ColourAmplitude, VisualVariable::ColourFrequency};

/// "geometric_amplitude", "geometric_frequency", "colour_amplitude", "colour_frequency".
std::string toString(VisualVariable variable);
std::optional<VisualVariable> visualVariableFromString(const std::string& name);

/// Unit of the variable's physical stimulus: "mm" (amplitude), "mm period" or "V".
std::string stimulusUnit(VisualVariable variable);

/// True for the frequencies, whose stimulus is a period length (longer period = lower level).
bool isFrequency(VisualVariable variable);

/// Waveforms of geometric waves; the perception study measured sine (reference), rectangle and
/// sawtooth (6.1.4.4); triangle is PACEMOD's fourth waveform.
enum class Waveform { Sine, Triangle, Sawtooth, Rectangle };

std::string toString(Waveform waveform);
std::optional<Waveform> waveformFromString(const std::string& name);

}  // namespace vicc_glyphs::perception
