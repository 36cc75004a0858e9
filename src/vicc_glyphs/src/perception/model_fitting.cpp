#include "vicc_glyphs/perception/model_fitting.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vicc_glyphs::perception {
namespace {

// Answers of one experiment group by stimulus level (adu, as shown in the survey).
using AnswersByLevel = std::map<double, std::vector<double>>;

struct Grouped {
  std::map<VisualVariable, AnswersByLevel> magnitudes;
  std::map<std::pair<VisualVariable, Waveform>, AnswersByLevel> calibrations;
};

Grouped groupAnswers(const std::vector<SurveyAnswer>& answers) {
  Grouped grouped;
  for (const SurveyAnswer& answer : answers) {
    const ExperimentKind kind = *experimentKind(answer.experiment);
    AnswersByLevel& target = kind.waveform ? grouped.calibrations[{kind.variable, *kind.waveform}]
                                           : grouped.magnitudes[kind.variable];
    target[answer.stimulus].push_back(answer.perceived);
  }
  return grouped;
}

struct LevelOutliers {
  int removed = 0;
  Truncation limits;
};

// Removes each level's outliers in place; returns how many were removed (in total and per
// level, with the limits the kept answers passed).
int removeOutliers(AnswersByLevel& levels, const ChebyshevParameters& parameters,
                   std::map<double, LevelOutliers>* per_level = nullptr) {
  int removed = 0;
  for (auto& [stimulus, values] : levels) {
    const OutlierLimits limits = chebyshevLimits(values, parameters);
    std::vector<double> kept;
    for (double value : values) {
      if (value >= limits.lower && value <= limits.upper) kept.push_back(value);
    }
    const int count = static_cast<int>(values.size() - kept.size());
    if (per_level) (*per_level)[stimulus] = {count, {limits.lower, limits.upper}};
    removed += count;
    values = std::move(kept);
  }
  return removed;
}

int answerCount(const AnswersByLevel& levels) {
  int count = 0;
  for (const auto& entry : levels) count += static_cast<int>(entry.second.size());
  return count;
}

VariableFit fitVariable(VisualVariable which, AnswersByLevel levels, const FitOptions& options) {
  const std::string name = toString(which);
  VariableFit fit;
  fit.variable = which;
  fit.answers = answerCount(levels);
  std::map<double, LevelOutliers> outliers_per_level;
  fit.outliers = removeOutliers(levels, options.outliers, &outliers_per_level);
  if (levels.size() < 3) {
    throw std::invalid_argument(name + ": answers for at least 3 stimulus levels are needed, got " +
                                std::to_string(levels.size()));
  }
  std::vector<double> stimuli, perceived;
  for (const auto& [stimulus, values] : levels) {
    if (values.size() < 2) {
      throw std::invalid_argument(name + ": stimulus level " + std::to_string(stimulus) +
                                  " has fewer than 2 answers after outlier removal");
    }
    stimuli.insert(stimuli.end(), values.size(), stimulus);
    perceived.insert(perceived.end(), values.begin(), values.end());
    LevelFit level;
    level.stimulus_adu = stimulus;
    const LevelOutliers& outliers = outliers_per_level[stimulus];
    level.answers = static_cast<int>(values.size()) + outliers.removed;
    level.outliers = outliers.removed;
    level.distribution = fitLevelDistribution(values, options.distribution, outliers.limits);
    fit.quantization_step = std::max(fit.quantization_step, level.distribution.interval50());
    fit.levels.push_back(level);
  }
  fit.stevens = fitStevensPowerFunction(stimuli, perceived);
  return fit;
}

CalibrationFit fitCalibration(VisualVariable which, Waveform waveform, AnswersByLevel levels,
                              const ChebyshevParameters& parameters) {
  CalibrationFit fit;
  fit.variable = which;
  fit.waveform = waveform;
  fit.answers = answerCount(levels);
  fit.outliers = removeOutliers(levels, parameters);
  const int n = answerCount(levels);
  if (levels.size() < 2 || n < 3) {
    throw std::invalid_argument(toString(which) + " " + toString(waveform) +
                                " calibration: needs answers for 2 reference levels");
  }
  Eigen::MatrixXd design(n, 2);
  Eigen::VectorXd chosen(n);
  int row = 0;
  for (const auto& [reference, values] : levels) {
    for (double value : values) {
      design(row, 0) = reference, design(row, 1) = 1.0, chosen(row) = value;
      ++row;
    }
  }
  const Eigen::Vector2d kl = design.colPivHouseholderQr().solve(chosen);
  fit.calibration = {kl(0), kl(1)};
  return fit;
}

}  // namespace

ModelFit fitPerceptionModel(const std::vector<SurveyAnswer>& answers, const PerceptionModel& base,
                            const FitOptions& options) {
  Grouped grouped = groupAnswers(answers);
  ModelFit result;
  result.model = base;
  for (auto& [which, levels] : grouped.magnitudes) {
    if (!base.variables.count(which)) {
      throw std::invalid_argument(toString(which) +
                                  ": the base model has no stimulus scale for it");
    }
    VariableFit fit = fitVariable(which, std::move(levels), options);
    VariableModel& model = result.model.variables[which];
    model.stevens = fit.stevens.function;
    model.quantization_step = fit.quantization_step;
    fit.level_count = result.model.levelCount(which, result.model.reference_size_mm);
    result.variables.push_back(fit);
  }
  for (auto& [key, levels] : grouped.calibrations) {
    if (!base.variables.count(key.first)) {
      throw std::invalid_argument(toString(key.first) + ": the base model lacks it");
    }
    CalibrationFit fit = fitCalibration(key.first, key.second, std::move(levels), options.outliers);
    result.model.variables[key.first].calibrations[key.second] = fit.calibration;
    result.calibrations.push_back(fit);
  }
  if (const std::string problem = result.model.problem(); !problem.empty()) {
    throw std::invalid_argument("fitted model is not usable: " + problem);
  }
  return result;
}

}  // namespace vicc_glyphs::perception
