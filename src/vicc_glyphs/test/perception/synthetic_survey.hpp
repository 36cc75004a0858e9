#pragma once
// Synthetic survey answers drawn from a known model, for testing the fitting tool: per
// stimulus level Gaussian answers about e(x) (or a two-component mixture about it), a share
// of gross outliers, and waveform calibration answers about h(x).

#include <random>
#include <vector>

#include "vicc_glyphs/perception/level_distribution.hpp"
#include "vicc_glyphs/perception/stevens_power_function.hpp"
#include "vicc_glyphs/perception/survey.hpp"

namespace vicc_glyphs::test {

struct SyntheticVariable {
  std::string experiment;  ///< e.g. "Ampl2"
  perception::StevensPowerFunction truth;
  std::vector<double> stimuli;  ///< adu levels shown
  double sigma = 1.0;           ///< answer spread at unimodal levels
  std::vector<double> bimodal;  ///< levels whose answers are the mixture below
  double mode_offset = 1.6;     ///< mixture: modes at e(x) -+ offset ...
  double mode_sigma = 0.8;      ///< ... with this spread
  int answers_per_level = 300;
  double outlier_share = 0.03;  ///< answers moved 7..10 adu away from e(x)
};

inline bool contains(const std::vector<double>& values, double x) {
  for (double v : values) {
    if (v == x) return true;
  }
  return false;
}

/// The distribution the answers of `stimulus` are drawn from (without outliers).
inline perception::LevelDistribution trueDistribution(const SyntheticVariable& v, double stimulus) {
  perception::LevelDistribution d;
  const double centre = v.truth.perceived(stimulus);
  if (contains(v.bimodal, stimulus)) {
    d.components = {{0.5, centre - v.mode_offset, v.mode_sigma},
                    {0.5, centre + v.mode_offset, v.mode_sigma}};
  } else {
    d.components = {{1.0, centre, v.sigma}};
  }
  return d;
}

inline void appendAnswers(const SyntheticVariable& v, std::mt19937& random,
                          std::vector<perception::SurveyAnswer>& answers, int* outliers = nullptr) {
  std::normal_distribution<double> unit(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (double stimulus : v.stimuli) {
    const perception::LevelDistribution d = trueDistribution(v, stimulus);
    for (int i = 0; i < v.answers_per_level; ++i) {
      const perception::GaussianComponent& g =
          d.components[d.isMixture() && uniform(random) < 0.5 ? 1 : 0];
      double value = g.mean + g.sigma * unit(random);
      if (uniform(random) < v.outlier_share) {
        value = d.mean() + (uniform(random) < 0.5 ? -1.0 : 1.0) * (7.0 + 3.0 * uniform(random));
        if (outliers) ++*outliers;
      }
      answers.push_back({stimulus, value, v.experiment, std::nullopt, 0});
    }
  }
}

/// Calibration answers: the waveform level chosen as equal to sine level x is k x + l + noise.
inline void appendCalibration(const std::string& experiment, double k, double l, double sigma,
                              std::mt19937& random,
                              std::vector<perception::SurveyAnswer>& answers) {
  std::normal_distribution<double> noise(0.0, sigma);
  for (double reference = 2; reference <= 10; reference += 1) {
    for (int i = 0; i < 60; ++i) {
      answers.push_back({reference, k * reference + l + noise(random), experiment, 6.0, 0});
    }
  }
}

}  // namespace vicc_glyphs::test
