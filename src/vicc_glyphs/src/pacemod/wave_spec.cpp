#include "vicc_glyphs/pacemod/wave_spec.hpp"

#include <cmath>
#include <sstream>

namespace vicc_glyphs {
namespace pacemod {

std::optional<Waveform> parseWaveform(const std::string& name) {
  if (name == "sine") return Waveform::Sine;
  if (name == "triangle") return Waveform::Triangle;
  if (name == "sawtooth") return Waveform::Sawtooth;
  if (name == "rectangle") return Waveform::Rectangle;
  return std::nullopt;
}

std::string waveformName(Waveform waveform) {
  switch (waveform) {
    case Waveform::Sine:
      return "sine";
    case Waveform::Triangle:
      return "triangle";
    case Waveform::Sawtooth:
      return "sawtooth";
    case Waveform::Rectangle:
      return "rectangle";
  }
  return "unknown";
}

std::string validate(const WaveSpec& spec) {
  if (!std::isfinite(spec.waves_per_mm) || !(spec.waves_per_mm > 0.0)) {
    return "waves_per_mm must be a finite number > 0";
  }
  if (!std::isfinite(spec.amplitude_mm) || !(spec.amplitude_mm >= 0.0)) {
    return "amplitude_mm must be a finite number >= 0";
  }
  return "";
}

std::string checkDisplacement(const char* name, double value_mm, double glyph_size_mm) {
  const double limit = kMaxDisplacementShareOfGlyph * glyph_size_mm;
  if (std::abs(value_mm) <= limit) return "";
  std::ostringstream message;
  message << name << " " << value_mm << " mm is larger than a quarter of the glyph's width ("
          << limit << " mm of " << glyph_size_mm << " mm)";
  return message.str();
}

}  // namespace pacemod
}  // namespace vicc_glyphs
