// The default model (config/perception_model.yaml) against the thesis's figures (Tables 6.1,
// 6.3), its level construction and the size-transfer rules of 6.1.5.
#include <gtest/gtest.h>

#include <cmath>

#include "vicc_glyphs/perception/perception_model.hpp"
#include "vicc_glyphs/perception/perception_model_yaml.hpp"

using namespace vicc_glyphs::perception;

namespace {

PerceptionModel defaultModel() {
  return loadPerceptionModel(std::string(VICC_GLYPHS_CONFIG_DIR) + "/perception_model.yaml");
}

}  // namespace

TEST(PerceptionModel, DefaultModelHasTheReportedLevelCountsAndExponents) {
  const PerceptionModel model = defaultModel();
  EXPECT_EQ(model.levelCount(VisualVariable::GeometricAmplitude, 50), 4);
  EXPECT_EQ(model.levelCount(VisualVariable::GeometricFrequency, 50), 5);
  EXPECT_EQ(model.levelCount(VisualVariable::ColourAmplitude, 50), 4);
  EXPECT_EQ(model.levelCount(VisualVariable::ColourFrequency, 50), 4);
  EXPECT_DOUBLE_EQ(model.variable(VisualVariable::GeometricAmplitude).stevens.b, 1.0604);
  EXPECT_DOUBLE_EQ(model.variable(VisualVariable::GeometricFrequency).stevens.b, 1.7918);
  EXPECT_DOUBLE_EQ(model.variable(VisualVariable::ColourAmplitude).stevens.b, 0.928);
  EXPECT_DOUBLE_EQ(model.variable(VisualVariable::ColourFrequency).stevens.b, 1.9463);
  EXPECT_DOUBLE_EQ(model.variable(VisualVariable::GeometricAmplitude).quantization_step, 2.91);
  EXPECT_DOUBLE_EQ(model.variable(VisualVariable::ColourFrequency).quantization_step, 1.14);
}

// The file says how a and c were chosen: e maps the stimulus range onto a perceived range with
// the same centre and the span (n - 0.5) dv.
TEST(PerceptionModel, DefaultAandCFollowTheDocumentedRule) {
  const PerceptionModel model = defaultModel();
  const std::map<VisualVariable, int> reported{{VisualVariable::GeometricAmplitude, 4},
                                               {VisualVariable::GeometricFrequency, 5},
                                               {VisualVariable::ColourAmplitude, 4},
                                               {VisualVariable::ColourFrequency, 4}};
  for (const auto& [which, count] : reported) {
    const VariableModel& v = model.variable(which);
    const double low = v.stevens.perceived(v.scale.adu_min);
    const double high = v.stevens.perceived(v.scale.adu_max);
    EXPECT_NEAR(high - low, (count - 0.5) * v.quantization_step, 1e-4) << toString(which);
    EXPECT_NEAR(0.5 * (low + high), 0.5 * (v.scale.adu_min + v.scale.adu_max), 1e-4)
        << toString(which);
  }
}

TEST(PerceptionModel, LevelsAreEquidistantInPerceptionAndStartAtTheWeakestStimulus) {
  const PerceptionModel model = defaultModel();
  const std::map<VisualVariable, double> weakest{{VisualVariable::GeometricAmplitude, 0.1},
                                                 {VisualVariable::GeometricFrequency, 5.1},
                                                 {VisualVariable::ColourAmplitude, 0.425},
                                                 {VisualVariable::ColourFrequency, 12.1}};
  for (const auto& [which, first] : weakest) {
    const VariableModel& v = model.variable(which);
    const VariableLevels levels = model.levels(which, 50);
    EXPECT_NEAR(levels.levels.front().stimulus, first, 1e-9) << toString(which);
    for (size_t i = 0; i < levels.levels.size(); ++i) {
      const StimulusLevel& level = levels.levels[i];
      EXPECT_NEAR(level.perceived_adu - levels.perceived_low, i * v.quantization_step, 1e-9);
      EXPECT_NEAR(v.stevens.perceived(level.stimulus_adu), level.perceived_adu, 1e-9);
      EXPECT_GE(level.stimulus, v.scale.physicalLow() - 1e-12);
      EXPECT_LE(level.stimulus, v.scale.physicalHigh() + 1e-12);
    }
  }
}

// Hand-computed: geometric amplitude level 1 at 50 mm has v = e(1) + 2.91 = 4.3175 adu,
// x = ((4.3175 - 0.620603) / 0.786897)^(1 / 1.0604) = 4.69804^0.943040 = 4.3018 adu = 0.43018 mm.
TEST(PerceptionModel, GeometricAmplitudeLevelMatchesHandComputation) {
  const StimulusLevel level = defaultModel().stimulus(VisualVariable::GeometricAmplitude, 1, 50);
  EXPECT_NEAR(level.perceived_adu, 4.3175, 1e-4);
  EXPECT_NEAR(level.stimulus, 0.43018, 2e-5);
}

TEST(PerceptionModel, FrequencyLevelsShortenThePeriod) {
  const VariableLevels levels = defaultModel().levels(VisualVariable::GeometricFrequency, 50);
  for (size_t i = 1; i < levels.levels.size(); ++i) {
    EXPECT_LT(levels.levels[i].stimulus, levels.levels[i - 1].stimulus);
    EXPECT_GT(levels.levels[i].per10mm(), levels.levels[i - 1].per10mm());
  }
  EXPECT_NEAR(levels.levels.front().per10mm(), 10.0 / 5.1, 1e-9);
}

TEST(PerceptionModel, SmallerGlyphsKeepTheMinimumAndScaleTheMaximum) {
  const PerceptionModel model = defaultModel();
  // w = 0.4, w_max = 0.4 + 0.25: amplitude range [0.1, 0.78] mm, three levels (Fig. 6.10).
  const VariableLevels amplitude = model.levels(VisualVariable::GeometricAmplitude, 20);
  EXPECT_NEAR(amplitude.range_low, 0.1, 1e-12);
  EXPECT_NEAR(amplitude.range_high, 1.2 * 0.65, 1e-12);
  EXPECT_EQ(amplitude.levels.size(), 3u);
  // dv, and with it the stimulus of every remaining level, is unchanged.
  const VariableLevels reference = model.levels(VisualVariable::GeometricAmplitude, 50);
  for (size_t i = 0; i < amplitude.levels.size(); ++i) {
    EXPECT_NEAR(amplitude.levels[i].stimulus, reference.levels[i].stimulus, 1e-12);
  }
  // Periods: the shortest (0.8 mm) stays, the longest becomes 5.1 * 0.65 mm.
  const VariableLevels frequency = model.levels(VisualVariable::GeometricFrequency, 20);
  EXPECT_NEAR(frequency.range_low, 0.8, 1e-12);
  EXPECT_NEAR(frequency.range_high, 5.1 * 0.65, 1e-12);
  EXPECT_NEAR(frequency.levels.front().stimulus, 5.1 * 0.65, 1e-9);
  // Colour amplitude does not depend on size.
  EXPECT_EQ(model.levels(VisualVariable::ColourAmplitude, 20).levels.size(), 4u);
}

TEST(PerceptionModel, EpsilonPointTwoLeavesTwoAmplitudeLevelsAtTwentyMillimetres) {
  PerceptionModel model = defaultModel();
  model.size_transfer.epsilon = 0.2;
  EXPECT_EQ(model.levelCount(VisualVariable::GeometricAmplitude, 20), 2);
}

TEST(PerceptionModel, LevelCountNeverGrowsAsTheGlyphShrinks) {
  const PerceptionModel model = defaultModel();
  for (VisualVariable which : kAllVisualVariables) {
    int previous = model.levelCount(which, 50);
    for (double size = 45; size >= 15; size -= 5) {
      const int count = model.levelCount(which, size);
      EXPECT_LE(count, previous) << toString(which) << " at " << size << " mm";
      previous = count;
    }
    EXPECT_EQ(model.levelCount(which, 80), model.levelCount(which, 50)) << toString(which);
  }
  // At 10 mm the longest colour period (12.1 * 0.45 = 5.4 mm) is below the shortest (5.9 mm):
  // the colour frequency cannot encode anything there.
  EXPECT_THROW(model.levels(VisualVariable::ColourFrequency, 10), std::domain_error);
}

TEST(PerceptionModel, BadSizesAndLevelsAreErrors) {
  PerceptionModel model = defaultModel();
  EXPECT_THROW(model.levels(VisualVariable::GeometricAmplitude, 0), std::invalid_argument);
  EXPECT_THROW(model.levels(VisualVariable::GeometricAmplitude, std::nan("")),
               std::invalid_argument);
  EXPECT_THROW(model.levels(VisualVariable::GeometricAmplitude, -5), std::invalid_argument);
  EXPECT_THROW(model.stimulus(VisualVariable::GeometricAmplitude, 4, 50), std::out_of_range);
  EXPECT_THROW(model.stimulus(VisualVariable::GeometricAmplitude, -1, 50), std::out_of_range);
  // Without epsilon a 2 mm glyph has a maximum amplitude (0.048 mm) below the minimum.
  model.size_transfer.epsilon = 0.0;
  EXPECT_THROW(model.levels(VisualVariable::GeometricAmplitude, 2), std::domain_error);
  model.variables.erase(VisualVariable::ColourFrequency);
  EXPECT_THROW(model.levels(VisualVariable::ColourFrequency, 50), std::out_of_range);
}

TEST(PerceptionModel, WaveformCalibrationAppliesToGeometricVariables) {
  PerceptionModel model = defaultModel();
  model.variables[VisualVariable::GeometricAmplitude].calibrations[Waveform::Rectangle] = {0.5,
                                                                                           1.0};
  const StimulusLevel sine = model.stimulus(VisualVariable::GeometricAmplitude, 2, 50);
  const StimulusLevel rectangle =
      model.stimulus(VisualVariable::GeometricAmplitude, 2, 50, Waveform::Rectangle);
  EXPECT_NEAR(rectangle.stimulus_adu, 0.5 * sine.stimulus_adu + 1.0, 1e-12);
  EXPECT_NEAR(rectangle.stimulus, 0.1 * rectangle.stimulus_adu, 1e-12);
  // No entry (triangle): like the sine.
  EXPECT_DOUBLE_EQ(
      model.stimulus(VisualVariable::GeometricAmplitude, 2, 50, Waveform::Triangle).stimulus,
      sine.stimulus);
}

TEST(StevensPowerFunction, InverseAndUnreachablePerception) {
  const StevensPowerFunction e{0.5, 2.0, 1.0};
  EXPECT_DOUBLE_EQ(e.perceived(3.0), 5.5);
  EXPECT_NEAR(e.stimulusFor(5.5), 3.0, 1e-12);
  EXPECT_THROW(e.stimulusFor(0.5), std::domain_error);
  EXPECT_FALSE(StevensPowerFunction({-1.0, 1.0, 0.0}).problem().empty());
}
