#pragma once
// Perceptually uniform quantization model of periodic contour modifications (thesis 6.1):
// per visual variable the stimulus scale (Table 6.1), the stimulus-to-perception function
// e(x) = a x^b + c, the quantization step dv in perceived adu (Table 6.3), the waveform
// calibration h(x) = k x + l (6.1.4.4) and the size-transfer rules of 6.1.5.
//
// Levels at the reference size: v_min = e(x_min), v_max = e(x_max) over the variable's stimulus
// range; level i has the perception v_min + i * dv (i = 0 .. floor((v_max - v_min) / dv)) and
// the stimulus e^-1 of it. Level 0 is the weakest stimulus (smallest amplitude, longest
// period, darkest colour amplitude).

#include <map>
#include <string>
#include <vector>

#include "vicc_glyphs/perception/stevens_power_function.hpp"
#include "vicc_glyphs/perception/stimulus_scale.hpp"
#include "vicc_glyphs/perception/visual_variable.hpp"

namespace vicc_glyphs::perception {

/// h(x) = k x + l: the stimulus (adu) of a waveform that is perceived like the sine wave's
/// stimulus x (adu).
struct WaveformCalibration {
  double k = 1.0;
  double l = 0.0;
  double apply(double sine_adu) const { return k * sine_adu + l; }
};

struct VariableModel {
  StimulusScale scale;
  StevensPowerFunction stevens;
  double quantization_step = 1.0;  ///< dv in perceived adu
  bool scales_with_size = true;    ///< false for the colour amplitude (6.1.5, first rule)
  /// Geometric variables only; a waveform without an entry is perceived like the sine.
  std::map<Waveform, WaveformCalibration> calibrations;
};

/// Size transfer (6.1.5) for a glyph of scale w = size / reference size (w < 1): the smaller
/// physical end of a range is scaled by w_min = max(w, min_scale), the larger by
/// w_max = min(1, w + epsilon); dv and with it the stimulus steps stay unchanged. Glyphs at
/// or above the reference size keep the reference stimuli in mm.
struct SizeTransfer {
  double min_scale = 1.0;  ///< w_min (1: minimum stimuli are not scaled)
  double epsilon = 0.0;    ///< e in w_max = w + e <= 1
};

/// One quantization level of a visual variable at a given glyph size.
struct StimulusLevel {
  int index = 0;
  double perceived_adu = 0.0;  ///< v_min + index * dv
  double stimulus_adu = 0.0;   ///< e^-1(perceived), calibrated for the waveform
  double stimulus = 0.0;       ///< physical: mm (amplitude), period mm (frequencies) or V
  /// Frequencies only: waves (or colour periods) per 10 mm of contour, 10 / period.
  double per10mm() const { return 10.0 / stimulus; }
};

/// The usable range and levels of one variable at one size.
struct VariableLevels {
  VisualVariable variable = VisualVariable::GeometricAmplitude;
  double size_mm = 0.0;
  double range_low = 0.0;  ///< physical range after the size transfer
  double range_high = 0.0;
  double perceived_low = 0.0;
  double perceived_high = 0.0;
  std::vector<StimulusLevel> levels;
};

class PerceptionModel {
 public:
  double reference_size_mm = 50.0;
  SizeTransfer size_transfer;
  std::map<VisualVariable, VariableModel> variables;

  /// The model of `variable`; throws std::out_of_range naming it if the model lacks it.
  const VariableModel& variable(VisualVariable variable) const;

  /// Levels of `variable` for a glyph `size_mm` wide. Throws std::invalid_argument for a size
  /// that is not finite and positive, and std::domain_error if the size leaves no usable
  /// range (the variable cannot encode data at that size).
  VariableLevels levels(VisualVariable variable, double size_mm,
                        Waveform waveform = Waveform::Sine) const;

  /// The level count of `variable` at `size_mm` (levels(...).levels.size()).
  int levelCount(VisualVariable variable, double size_mm) const;

  /// Stimulus of level `level` (0-based); throws std::out_of_range naming the variable, level
  /// and count when the level does not exist at that size.
  StimulusLevel stimulus(VisualVariable variable, int level, double size_mm,
                         Waveform waveform = Waveform::Sine) const;

  /// Empty if the model is usable (every variable valid, dv > 0, reference size > 0,
  /// w_min in (0, 1], e >= 0), else the reason naming the variable and field.
  std::string problem() const;
};

/// Level of a data value on a variable with `level_count` levels when the data domain
/// [lower, upper] is split into equal bins (upper itself is the last level). Throws
/// std::domain_error for NaN or a value outside the domain, std::invalid_argument for an empty
/// domain or a count < 1; `name` is used in the messages.
int levelForValue(double value, double lower, double upper, int level_count,
                  const std::string& name = "value");

}  // namespace vicc_glyphs::perception
