// "vicc_glyph fit-model" end to end: a synthetic survey CSV in, a model file out that loads
// and has the true level count.
#include <gtest/gtest.h>

#include <fstream>

#include "../support/tool_run.hpp"
#include "synthetic_survey.hpp"
#include "vicc_glyphs/perception/perception_model_yaml.hpp"

using namespace vicc_glyphs::perception;

namespace {

class FitModelCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = vicc_glyphs::test::freshTestDirectory(
        "vicc_glyph_fit_", ::testing::UnitTest::GetInstance()->current_test_info()->name());
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
};

void writeSurvey(const std::vector<SurveyAnswer>& answers, const std::filesystem::path& path) {
  std::ofstream file(path);
  file << "stimulus,perceived,experiment,second_stimulus\n";
  for (const SurveyAnswer& a : answers) {
    file << a.stimulus << "," << a.perceived << "," << a.experiment << ",\n";
  }
}

}  // namespace

TEST_F(FitModelCliTest, WritesAModelWithTheRecoveredParameters) {
  vicc_glyphs::test::SyntheticVariable colour;
  colour.experiment = "ColAmpl2";
  colour.truth = {1.246774, 0.928, -0.399274};
  colour.stimuli = {1, 1.5, 2, 2.5, 3, 3.5, 4, 4.5, 5};
  colour.sigma = 1.23 / (2.0 * 0.6744897501960817);
  colour.answers_per_level = 1000;
  std::mt19937 random(3);
  std::vector<SurveyAnswer> answers;
  vicc_glyphs::test::appendAnswers(colour, random, answers);
  const auto csv = dir_ / "survey.csv", model = dir_ / "fitted.yaml";
  writeSurvey(answers, csv);

  const auto run =
      vicc_glyphs::test::runTool("fit-model " + csv.string() + " --out " + model.string(), dir_);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("colour_amplitude: 9000 answers"), std::string::npos) << run.out;
  const PerceptionModel fitted = loadPerceptionModel(model.string());
  const VariableModel& v = fitted.variable(VisualVariable::ColourAmplitude);
  EXPECT_NEAR(v.stevens.b, 0.928, 0.11);  // 3.5 standard errors of b (0.033)
  EXPECT_NEAR(v.quantization_step, 1.23, 0.08);
  EXPECT_EQ(fitted.levelCount(VisualVariable::ColourAmplitude, 50), 4);
  EXPECT_NE(vicc_glyphs::test::readText(model).find("# Perception model fitted by"),
            std::string::npos);
}

TEST_F(FitModelCliTest, BadInputFailsWithAMessage) {
  const auto csv = dir_ / "bad.csv";
  std::ofstream(csv) << "stimulus,perceived,experiment,second_stimulus\n1,2,Nope,\n";
  const auto bad = vicc_glyphs::test::runTool(
      "fit-model " + csv.string() + " --out " + (dir_ / "m.yaml").string(), dir_);
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("unknown experiment 'Nope'"), std::string::npos) << bad.err;
  const auto usage = vicc_glyphs::test::runTool("fit-model " + csv.string(), dir_);
  EXPECT_EQ(usage.exit_code, 2);
  EXPECT_NE(usage.err.find("missing --out"), std::string::npos) << usage.err;
  const auto p1 =
      vicc_glyphs::test::runTool("fit-model " + csv.string() + " --out x.yaml --p1 2", dir_);
  EXPECT_EQ(p1.exit_code, 2);
  // A model written over its survey or its base model would destroy them.
  const auto size_before = std::filesystem::file_size(csv);
  const auto over_survey =
      vicc_glyphs::test::runTool("fit-model " + csv.string() + " --out " + csv.string(), dir_);
  EXPECT_EQ(over_survey.exit_code, 2);
  EXPECT_NE(over_survey.err.find("SURVEY and --out are the same file"), std::string::npos)
      << over_survey.err;
  EXPECT_EQ(std::filesystem::file_size(csv), size_before);
  const auto over_base = vicc_glyphs::test::runTool("fit-model " + csv.string() + " --base " +
                                                        (dir_ / "x" / ".." / "b.yaml").string() +
                                                        " --out " + (dir_ / "b.yaml").string(),
                                                    dir_);
  EXPECT_EQ(over_base.exit_code, 2);
  EXPECT_NE(over_base.err.find("--base and --out are the same file"), std::string::npos)
      << over_base.err;
}
