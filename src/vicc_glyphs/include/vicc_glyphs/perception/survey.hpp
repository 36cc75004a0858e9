#pragma once
// Survey answers (thesis 6.1.3.2, Table 6.2) as CSV with the header
//   stimulus,perceived,experiment,second_stimulus
// one answer per line: the stimulus shown (adu), the magnitude answered (adu), the experiment
// type (Ampl1, Ampl2, Freq1, Freq2, ColAmpl1, ColAmpl2, ColFreq1, ColFreq2 estimate a
// magnitude; SawtAmpl, RectAmpl, SawtFreq, RectFreq calibrate a waveform against the sine:
// stimulus = the sine reference's adu, perceived = the adu of the waveform chosen as equal)
// and the second visual variable's stimulus (adu; empty if there is none).

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "vicc_glyphs/perception/visual_variable.hpp"

namespace vicc_glyphs::perception {

struct SurveyFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct SurveyAnswer {
  double stimulus = 0.0;
  double perceived = 0.0;
  std::string experiment;
  std::optional<double> second_stimulus;
  int line = 0;  ///< in the file, for messages
};

/// What an experiment measures: a magnitude estimation of `variable`, or (with `waveform`) the
/// calibration of that waveform against the sine.
struct ExperimentKind {
  VisualVariable variable = VisualVariable::GeometricAmplitude;
  std::optional<Waveform> waveform;
};

/// The kind of a Table 6.2 experiment name; nullopt for an unknown name.
std::optional<ExperimentKind> experimentKind(const std::string& name);

/// Parses survey CSV text; errors name the line and column. Unknown experiments, non-numeric
/// or non-finite values and a wrong header are errors.
std::vector<SurveyAnswer> parseSurveyCsv(const std::string& text);
std::vector<SurveyAnswer> loadSurveyCsv(const std::string& path);

}  // namespace vicc_glyphs::perception
