// The fitting tool on synthetic survey data drawn from known models: it must recover a, b, c,
// the quantization step, the level count and the waveform calibration.
#include <gtest/gtest.h>

#include <cmath>

#include "synthetic_survey.hpp"
#include "vicc_glyphs/perception/chebyshev_outliers.hpp"
#include "vicc_glyphs/perception/model_fitting.hpp"
#include "vicc_glyphs/perception/perception_model_yaml.hpp"

using namespace vicc_glyphs::perception;
using vicc_glyphs::test::SyntheticVariable;

namespace {

PerceptionModel defaultModel() {
  return loadPerceptionModel(std::string(VICC_GLYPHS_CONFIG_DIR) + "/perception_model.yaml");
}

// Geometric amplitude as in the default model: sigma such that the 50 % interval of a
// unimodal level is 2.91 adu (2 * 0.67449 sigma), bimodal answers (narrower interval) at the
// medium levels. 1500 answers per level over the whole stimulus range 1..12: with the
// survey's 300 per level on 2..10 the standard error of b alone is 0.08 (Fisher information).
SyntheticVariable amplitudeSurvey() {
  SyntheticVariable v;
  v.experiment = "Ampl2";
  v.truth = defaultModel().variable(VisualVariable::GeometricAmplitude).stevens;
  v.stimuli = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
  v.answers_per_level = 1500;
  v.sigma = 2.91 / (2.0 * 0.6744897501960817);
  v.bimodal = {5, 6, 7};
  v.mode_offset = 1.3;
  v.mode_sigma = 0.9;
  return v;
}

SyntheticVariable frequencySurvey() {
  SyntheticVariable v;
  v.experiment = "Freq1";
  v.truth = defaultModel().variable(VisualVariable::GeometricFrequency).stevens;
  v.stimuli = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
  v.answers_per_level = 1500;
  v.sigma = 2.01 / (2.0 * 0.6744897501960817);
  return v;
}

const VariableFit& fitOf(const ModelFit& fit, VisualVariable which) {
  for (const VariableFit& v : fit.variables) {
    if (v.variable == which) return v;
  }
  throw std::out_of_range("no fit for " + toString(which));
}

double largestTrueInterval(const SyntheticVariable& v) {
  double largest = 0.0;
  for (double x : v.stimuli) largest = std::max(largest, trueDistribution(v, x).interval50());
  return largest;
}

}  // namespace

TEST(ChebyshevOutliers, HandComputedTwoStepCase) {
  // Step 1: mean 5.909, sd 3.961, k1 sd = 6.469 removes 14 and -3; step 2: mean 6, sd 1.2247,
  // k2 sd = 2.928: 14 and -3 are outliers, 8 (2 away) is not.
  const std::vector<double> values{4, 5, 5, 6, 6, 6, 7, 7, 8, 14, -3};
  const std::vector<bool> outlier = chebyshevOutliers(values);
  for (size_t i = 0; i < values.size(); ++i) {
    EXPECT_EQ(outlier[i], values[i] == 14 || values[i] == -3) << values[i];
  }
  // Stricter second step (p2 = 0.5, k2 = 1.414, limit 1.732): 4 and 8 go too.
  const std::vector<bool> strict = chebyshevOutliers(values, {0.375, 0.5});
  EXPECT_TRUE(strict[0]);
  EXPECT_TRUE(strict[8]);
  EXPECT_FALSE(strict[3]);
  EXPECT_THROW(chebyshevOutliers(values, {0.0, 0.175}), std::invalid_argument);
}

TEST(ChebyshevOutliers, EqualValuesAfterTheFirstStepFallBackToItsLimits) {
  // Step 1 (mean 6.36, sd 4.52, limit 7.38) removes 20; the rest are all 5 (sd 0), so the
  // step-1 limits decide: only 20 is an outlier.
  const std::vector<double> values{5, 5, 5, 5, 5, 5, 5, 5, 5, 20};
  const std::vector<bool> outlier = chebyshevOutliers(values);
  EXPECT_TRUE(outlier[9]);
  for (int i = 0; i < 9; ++i) EXPECT_FALSE(outlier[i]);
  // With one 6 among them step 2 has sd 0.32 and its limit 0.76 flags the 6: the method is
  // strict with integer answers.
  const std::vector<double> with_six{5, 5, 5, 5, 5, 5, 5, 5, 5, 6, 20};
  EXPECT_TRUE(chebyshevOutliers(with_six)[9]);
}

TEST(LevelDistribution, MixtureIntervalIsBetweenTheQuartilesOfTheSuperposition) {
  LevelDistribution single;
  single.components = {{1.0, 3.0, 2.0}};
  EXPECT_NEAR(single.interval50(), 2.0 * 0.6744897501960817 * 2.0, 1e-6);
  EXPECT_NEAR(single.quantile(0.5), 3.0, 1e-9);
  LevelDistribution mixture;
  mixture.components = {{0.5, -2.0, 0.5}, {0.5, 2.0, 0.5}};
  // Symmetric: q75 solves 0.5 Phi((q-2)/0.5) + 0.5 Phi((q+2)/0.5) = 0.75 -> q = 2 (to 1e-6).
  EXPECT_NEAR(mixture.quantile(0.75), 2.0, 1e-4);
  EXPECT_NEAR(mixture.interval50(), 4.0, 2e-4);
}

TEST(ModelFitting, RecoversAmplitudeModelStepAndLevelCountDespiteOutliers) {
  std::mt19937 random(20260);
  std::vector<SurveyAnswer> answers;
  int injected = 0;
  const SyntheticVariable survey = amplitudeSurvey();
  appendAnswers(survey, random, answers, &injected);
  const ModelFit fit = fitPerceptionModel(answers, defaultModel());
  const VariableFit& amplitude = fitOf(fit, VisualVariable::GeometricAmplitude);

  // Tolerances: 3.5 standard errors of this design (Fisher information: a 0.039, b 0.018,
  // c 0.080).
  EXPECT_TRUE(amplitude.stevens.converged);
  EXPECT_NEAR(amplitude.stevens.function.b, survey.truth.b, 0.065);
  EXPECT_NEAR(amplitude.stevens.function.a, survey.truth.a, 0.14);
  EXPECT_NEAR(amplitude.stevens.function.c, survey.truth.c, 0.28);
  for (double x : survey.stimuli) {
    EXPECT_NEAR(amplitude.stevens.function.perceived(x), survey.truth.perceived(x), 0.15) << x;
  }
  // The outliers (about 3 %) are removed, and not much else. The method is strict: the
  // outliers inflate the step-1 sd, so step 1 keeps about +-2 sd, and step 2's limit
  // (2.39 x the sd of that truncated sample) also flags about 3.5 % of the good answers.
  EXPECT_GE(amplitude.outliers, injected * 9 / 10);
  EXPECT_LE(amplitude.outliers, injected + amplitude.answers / 20);
  // Bimodal levels are fitted with mixtures, the others with single Gaussians.
  for (const LevelFit& level : amplitude.levels) {
    EXPECT_EQ(level.distribution.isMixture(),
              vicc_glyphs::test::contains(survey.bimodal, level.stimulus_adu))
        << level.stimulus_adu;
  }
  const double true_step = largestTrueInterval(survey);
  EXPECT_NEAR(amplitude.quantization_step, true_step, 0.06 * true_step);
  EXPECT_EQ(amplitude.level_count, 4);
  EXPECT_EQ(fit.model.levelCount(VisualVariable::GeometricAmplitude, 50), 4);
}

TEST(ModelFitting, RecoversTheFrequencyExponentAndFiveLevels) {
  std::mt19937 random(7);
  std::vector<SurveyAnswer> answers;
  const SyntheticVariable survey = frequencySurvey();
  appendAnswers(survey, random, answers);
  const ModelFit fit = fitPerceptionModel(answers, defaultModel());
  const VariableFit& frequency = fitOf(fit, VisualVariable::GeometricFrequency);
  // 3.5 standard errors (a 0.0050, b 0.0185, c 0.030).
  EXPECT_NEAR(frequency.stevens.function.b, 1.7918, 0.065);
  EXPECT_NEAR(frequency.stevens.function.a, survey.truth.a, 0.0175);
  EXPECT_NEAR(frequency.stevens.function.c, survey.truth.c, 0.105);
  EXPECT_NEAR(frequency.quantization_step, 2.01, 0.1);
  EXPECT_EQ(frequency.level_count, 5);
  // Variables without answers keep the base model.
  EXPECT_DOUBLE_EQ(fit.model.variable(VisualVariable::ColourAmplitude).stevens.b, 0.928);
}

TEST(ModelFitting, RecoversTheWaveformCalibration) {
  std::mt19937 random(11);
  std::vector<SurveyAnswer> answers;
  appendAnswers(frequencySurvey(), random, answers);
  vicc_glyphs::test::appendCalibration("SawtAmpl", 0.9, 0.5, 0.8, random, answers);
  const ModelFit fit = fitPerceptionModel(answers, defaultModel());
  ASSERT_EQ(fit.calibrations.size(), 1u);
  const WaveformCalibration h =
      fit.model.variable(VisualVariable::GeometricAmplitude).calibrations.at(Waveform::Sawtooth);
  EXPECT_NEAR(h.k, 0.9, 0.03);
  EXPECT_NEAR(h.l, 0.5, 0.2);
}

TEST(ModelFitting, TooFewLevelsIsAnErrorNamingTheVariable) {
  std::vector<SurveyAnswer> answers;
  for (double x : {2.0, 3.0}) {
    for (int i = 0; i < 5; ++i) answers.push_back({x, x + 0.1 * i, "ColFreq2", 3.0, 0});
  }
  try {
    fitPerceptionModel(answers, defaultModel());
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("colour_frequency"), std::string::npos) << e.what();
  }
}

TEST(SurveyCsv, ParsesAndNamesTheBadLine) {
  const auto answers = parseSurveyCsv(
      "stimulus,perceived,experiment,second_stimulus\n3,4,Ampl1,6\n5,5.5,ColFreq2,\n");
  ASSERT_EQ(answers.size(), 2u);
  EXPECT_EQ(answers[0].second_stimulus.value_or(-1), 6.0);
  EXPECT_FALSE(answers[1].second_stimulus.has_value());
  const auto error = [](const std::string& text) {
    try {
      parseSurveyCsv(text);
    } catch (const SurveyFileError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string header = "stimulus,perceived,experiment,second_stimulus\n";
  EXPECT_NE(error("x,y\n").find("line 1: the header"), std::string::npos);
  EXPECT_NE(error(header + "3,4,Ampl1,6\n3,x,Ampl1,6\n").find("line 3: perceived"),
            std::string::npos);
  EXPECT_NE(error(header + "3,4,Wobble,6\n").find("unknown experiment 'Wobble'"),
            std::string::npos);
  EXPECT_NE(error(header + "3,nan,Ampl1,6\n").find("line 2: perceived must be a finite"),
            std::string::npos);
  EXPECT_NE(error(header + "3,4,Ampl1\n").find("expected 4 fields"), std::string::npos);
}

TEST(LevelDistribution, TruncationCorrectionRestoresTheDeviation) {
  // N(1, 2) cut to [1 - 4, 1 + 4] (+-2 sd keeps 95.4 %): the sample sd is 0.88 x 2.
  std::mt19937 random(5);
  std::normal_distribution<double> normal(1.0, 2.0);
  std::vector<double> kept;
  while (kept.size() < 20000) {
    const double x = normal(random);
    if (std::abs(x - 1.0) <= 4.0) kept.push_back(x);
  }
  const LevelDistribution plain = fitGaussian(kept);
  const LevelDistribution corrected = fitGaussian(kept, {}, {-3.0, 5.0});
  EXPECT_NEAR(plain.components[0].sigma, 0.88 * 2.0, 0.03);
  EXPECT_NEAR(corrected.components[0].sigma, 2.0, 0.04);
  EXPECT_NEAR(corrected.components[0].mean, 1.0, 0.04);
}
