#include "fit_command.hpp"

#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "command_line.hpp"
#include "model_path.hpp"
#include "vicc_glyphs/perception/model_fitting.hpp"
#include "vicc_glyphs/perception/perception_model_yaml.hpp"

namespace vicc_glyphs::tools {
namespace {

using namespace vicc_glyphs::perception;

const std::vector<OptionSpec>& fitOptions() {
  static const std::vector<OptionSpec> specs{
      {"out", "MODEL.yaml", "model file to write (required)"},
      {"base", "MODEL.yaml",
       "model giving stimulus scales, size transfer and unfitted variables"
       " (default: config/perception_model.yaml)"},
      {"p1", "P", "Chebyshev step-1 outlier probability (default 0.375)"},
      {"p2", "P", "Chebyshev step-2 outlier probability (default 0.175)"},
      {"help", "", "show this help"},
  };
  return specs;
}

void printUsage(std::ostream& out) {
  out << "usage: vicc_glyph fit-model SURVEY.csv --out MODEL.yaml [--base MODEL.yaml]\n"
         "                           [--p1 P] [--p2 P]\n\n"
         "Fits the perception model to survey answers (CSV header:\n"
         "stimulus,perceived,experiment,second_stimulus; experiments as in thesis Table 6.2):\n"
         "Chebyshev outlier removal, e(x) = a x^b + c, per-level Gaussian or mixture, dv, "
         "levels.\n\n"
      << formatOptions(fitOptions());
}

void printVariableFit(const VariableFit& fit, std::ostream& out) {
  const StevensPowerFunction& e = fit.stevens.function;
  out << std::fixed << std::setprecision(4) << toString(fit.variable) << ": " << fit.answers
      << " answers, " << fit.outliers << " outliers; e(x) = " << e.a << " x^" << e.b << " + " << e.c
      << " (rms " << fit.stevens.rms_residual << (fit.stevens.converged ? "" : ", NOT CONVERGED")
      << "); dv " << fit.quantization_step << " adu; " << fit.level_count << " levels\n";
  for (const LevelFit& level : fit.levels) {
    out << "  stimulus " << std::setw(7) << level.stimulus_adu << ": " << std::setw(4)
        << level.answers << " answers, " << std::setw(3) << level.outliers << " outliers, "
        << (level.distribution.isMixture() ? "mixture " : "gaussian") << " mean "
        << level.distribution.mean() << ", 50% interval " << level.distribution.interval50()
        << "\n";
  }
}

std::string fileHeader(const std::string& survey, const ModelFit& fit, const FitOptions& options) {
  std::ostringstream text;
  text << "Perception model fitted by vicc_glyph fit-model from " << survey << "\n"
       << "(Chebyshev p1 = " << options.outliers.p1 << ", p2 = " << options.outliers.p2
       << "; fitted: ";
  for (const VariableFit& v : fit.variables) text << toString(v.variable) << " ";
  for (const CalibrationFit& c : fit.calibrations) {
    text << toString(c.variable) << "/" << toString(c.waveform) << " ";
  }
  text << "; the rest from the base model). Format: see config/perception_model.yaml.";
  return text.str();
}

}  // namespace

int runFitCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  std::string survey, output, base;  // base: empty for the default model, found below
  FitOptions options;
  const auto read = [&](const ParsedArguments& parsed) {
    if (parsed.positional.size() != 1) throw UsageError("expected one SURVEY.csv file");
    survey = parsed.positional.front();
    output = parsed.value("out");
    if (output.empty()) throw UsageError("missing --out MODEL.yaml");
    if (parsed.has("base")) base = parsed.value("base");
    if (parsed.has("p1")) options.outliers.p1 = parseNumber("p1", parsed.value("p1"), 1e-6, 1.0);
    if (parsed.has("p2")) options.outliers.p2 = parseNumber("p2", parsed.value("p2"), 1e-6, 1.0);
    requireDistinctFiles({{"SURVEY", survey}, {"--base", base}, {"--out", output}});
  };
  const std::optional<int> done =
      readCommandLine("fit-model", args, fitOptions(), printUsage, out, err, read);
  if (done) return *done;
  try {
    const std::vector<SurveyAnswer> answers = loadSurveyCsv(survey);
    // Without answers the "fitted" model would be the base model, written as if fitted.
    if (answers.empty()) throw std::runtime_error(survey + ": the table has no answers");
    const ModelFit fit = fitPerceptionModel(
        answers, loadPerceptionModel(perceptionModelPathOrDefault(base, "base")), options);
    if (fit.variables.empty() && fit.calibrations.empty()) {
      throw std::runtime_error(survey + ": no variable or calibration could be fitted");
    }
    for (const VariableFit& v : fit.variables) printVariableFit(v, out);
    for (const CalibrationFit& c : fit.calibrations) {
      out << toString(c.variable) << " " << toString(c.waveform)
          << " calibration: h(x) = " << c.calibration.k << " x + " << c.calibration.l << " ("
          << c.answers << " answers, " << c.outliers << " outliers)\n";
    }
    savePerceptionModel(fit.model, output, fileHeader(survey, fit, options));
    out << "wrote " << output << "\n";
  } catch (const std::exception& e) {
    err << "vicc_glyph fit-model: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace vicc_glyphs::tools
