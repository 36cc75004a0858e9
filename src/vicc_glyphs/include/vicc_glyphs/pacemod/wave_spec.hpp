#pragma once
// Parameters of a periodic geometric modification (thesis 6.2.4.1): waveform, frequency and
// amplitude in physical units of the glyph (millimetres at a given glyph width).

#include <optional>
#include <string>

namespace vicc_glyphs {
namespace pacemod {

enum class Waveform { Sine, Triangle, Sawtooth, Rectangle };

struct WaveSpec {
  Waveform waveform = Waveform::Sine;
  double waves_per_mm = 0.2;  ///< frequency: waves per millimetre of contour arc length (> 0)
  double amplitude_mm = 0.5;  ///< peak offset from the original contour in millimetres (>= 0)
};

/// "sine", "triangle", "sawtooth", "rectangle"; nullopt for anything else.
std::optional<Waveform> parseWaveform(const std::string& name);
std::string waveformName(Waveform waveform);

/// The largest wave amplitude or inflation offset, as a share of the glyph's width. The
/// perception model's levels stay far below it (1.2 mm of 50 mm); beyond it a modification
/// would not draw the icon any more (and the polygon check's grid would grow without bound).
inline constexpr double kMaxDisplacementShareOfGlyph = 0.25;

/// Empty when the displacement `value_mm` of the field `name` is within
/// kMaxDisplacementShareOfGlyph of `glyph_size_mm`, else a message naming both.
std::string checkDisplacement(const char* name, double value_mm, double glyph_size_mm);

/// Empty when valid, else a message naming the offending field ("waves_per_mm", "amplitude_mm").
std::string validate(const WaveSpec& spec);

}  // namespace pacemod
}  // namespace vicc_glyphs
