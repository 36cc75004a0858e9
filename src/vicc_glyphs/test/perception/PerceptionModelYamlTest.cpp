// Model-file reading errors name the key; writing and reading back gives the same model.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "vicc_glyphs/perception/perception_model_yaml.hpp"

using namespace vicc_glyphs::perception;

namespace {

std::string defaultText() {
  std::ifstream file(std::string(VICC_GLYPHS_CONFIG_DIR) + "/perception_model.yaml");
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

// The error message of parsing `text`, or "" if it parsed.
std::string errorOf(const std::string& text) {
  try {
    parsePerceptionModel(text);
  } catch (const ModelFileError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(PerceptionModelYaml, ErrorsNameTheKey) {
  const std::string text = defaultText();
  EXPECT_NE(errorOf(replaced(text, "b: 1.0604", "bb: 1.0604"))
                .find("unknown key variables.geometric_amplitude.stevens.bb"),
            std::string::npos);
  EXPECT_NE(errorOf(replaced(text, "    quantization_step: 2.01\n", ""))
                .find("missing key variables.geometric_frequency.quantization_step"),
            std::string::npos);
  EXPECT_NE(errorOf(replaced(text, "b: 0.928", "b: fast"))
                .find("variables.colour_amplitude.stevens.b must be a number"),
            std::string::npos);
  EXPECT_NE(errorOf(replaced(text, "value: [12.1, 5.9]", "value: [12.1]"))
                .find("variables.colour_frequency.stimulus.value must be a list of two numbers"),
            std::string::npos);
  EXPECT_NE(errorOf(replaced(text, "geometric_frequency:", "geometric_freq:"))
                .find("unknown key variables.geometric_freq"),
            std::string::npos);
  EXPECT_NE(errorOf(replaced(text, "quantization_step: 1.23", "quantization_step: -1"))
                .find("variables.colour_amplitude.quantization_step must be > 0"),
            std::string::npos);
  EXPECT_NE(errorOf(replaced(text, "sawtooth: {k: 1.0", "zigzag: {k: 1.0"))
                .find("unknown key variables.geometric_amplitude.waveform_calibration.zigzag"),
            std::string::npos);
  const std::string twice = replaced(text, "b: 1.0604,", "b: 1.0604, b: 2,");
  EXPECT_NE(errorOf(twice).find("key variables.geometric_amplitude.stevens.b is given twice"),
            std::string::npos)
      << errorOf(twice);
  EXPECT_NE(errorOf("variables: [1, 2"), "");
  EXPECT_NE(errorOf("").find("the model file must be a map"), std::string::npos);
}

TEST(PerceptionModelYaml, ExpectedLevelsMustMatchTheDerivedCount) {
  const std::string message =
      errorOf(replaced(defaultText(), "quantization_step: 2.91", "quantization_step: 2.0"));
  EXPECT_NE(message.find("variables.geometric_amplitude.expected_levels is 4"), std::string::npos)
      << message;
  EXPECT_NE(message.find("give 6 levels"), std::string::npos) << message;
}

TEST(PerceptionModelYaml, WrittenModelReadsBackTheSame) {
  const PerceptionModel model = parsePerceptionModel(defaultText());
  const std::string written = perceptionModelToYaml(model, "fitted for a test\nsecond line");
  EXPECT_EQ(written.rfind("# fitted for a test\n# second line\n", 0), 0u);
  const PerceptionModel back = parsePerceptionModel(written);
  EXPECT_DOUBLE_EQ(back.size_transfer.epsilon, model.size_transfer.epsilon);
  for (VisualVariable which : kAllVisualVariables) {
    const VariableModel& a = model.variable(which);
    const VariableModel& b = back.variable(which);
    EXPECT_NEAR(b.stevens.a, a.stevens.a, 1e-6);
    EXPECT_NEAR(b.stevens.b, a.stevens.b, 1e-6);
    EXPECT_NEAR(b.stevens.c, a.stevens.c, 1e-6);
    EXPECT_DOUBLE_EQ(b.quantization_step, a.quantization_step);
    EXPECT_DOUBLE_EQ(b.scale.value_at_max, a.scale.value_at_max);
    EXPECT_EQ(b.scales_with_size, a.scales_with_size);
    EXPECT_EQ(b.calibrations.size(), a.calibrations.size());
  }
}

TEST(PerceptionModelYaml, MissingFileIsAnError) {
  EXPECT_THROW(loadPerceptionModel("/nonexistent/model.yaml"), ModelFileError);
}
