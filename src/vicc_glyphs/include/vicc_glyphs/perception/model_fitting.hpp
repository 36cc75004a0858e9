#pragma once
// Derives the perception model from survey answers (thesis 6.1.3.3): per visual variable,
// two-step Chebyshev outlier removal per stimulus level, e(x) = a x^b + c by non-linear least
// squares, a Gaussian or two-component mixture per level with its 50 % interval, dv = the
// largest interval, and the level count; per waveform, h(x) = k x + l by least squares.

#include <map>
#include <vector>

#include "vicc_glyphs/perception/chebyshev_outliers.hpp"
#include "vicc_glyphs/perception/level_distribution.hpp"
#include "vicc_glyphs/perception/perception_model.hpp"
#include "vicc_glyphs/perception/stevens_fit.hpp"
#include "vicc_glyphs/perception/survey.hpp"

namespace vicc_glyphs::perception {

struct LevelFit {
  double stimulus_adu = 0.0;
  int answers = 0;
  int outliers = 0;
  LevelDistribution distribution;  ///< of the answers kept
};

struct VariableFit {
  VisualVariable variable = VisualVariable::GeometricAmplitude;
  int answers = 0;
  int outliers = 0;
  StevensFit stevens;
  std::vector<LevelFit> levels;  ///< by increasing stimulus
  double quantization_step = 0.0;
  int level_count = 0;  ///< at the reference size
};

struct CalibrationFit {
  VisualVariable variable = VisualVariable::GeometricAmplitude;
  Waveform waveform = Waveform::Sawtooth;
  int answers = 0;
  int outliers = 0;
  WaveformCalibration calibration;
};

struct FitOptions {
  ChebyshevParameters outliers;
  DistributionOptions distribution;
};

struct ModelFit {
  PerceptionModel model;  ///< the base model with the fitted parts replaced
  std::vector<VariableFit> variables;
  std::vector<CalibrationFit> calibrations;
};

/// Fits every variable and waveform that has answers; the rest of `base` (stimulus scales,
/// size transfer, variables without answers) is kept. Throws std::invalid_argument naming the
/// variable when its answers cannot be fitted (fewer than 3 stimulus levels, a level with
/// fewer than 2 answers after outlier removal, a variable the base model lacks).
ModelFit fitPerceptionModel(const std::vector<SurveyAnswer>& answers, const PerceptionModel& base,
                            const FitOptions& options = {});

}  // namespace vicc_glyphs::perception
