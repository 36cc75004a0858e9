// "vicc_glyph levels" run like a user: tables for 50 and 20 mm, errors with exit codes.
#include <gtest/gtest.h>

#include "../support/tool_run.hpp"

using vicc_glyphs::test::runTool;

namespace {

class LevelsCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = vicc_glyphs::test::freshTestDirectory(
        "vicc_glyph_levels_", ::testing::UnitTest::GetInstance()->current_test_info()->name());
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  vicc_glyphs::test::ToolRun run(const std::string& args) const { return runTool(args, dir_); }
  std::filesystem::path dir_;
};

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST_F(LevelsCliTest, ReferenceSizeTableHasTheReportedCountsAndStimuli) {
  const auto result = run("levels --size-mm 50");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(contains(result.out, "geometric_amplitude: 4 levels")) << result.out;
  EXPECT_TRUE(contains(result.out, "geometric_frequency: 5 levels")) << result.out;
  EXPECT_TRUE(contains(result.out, "colour_amplitude: 4 levels")) << result.out;
  EXPECT_TRUE(contains(result.out, "colour_frequency: 4 levels")) << result.out;
  // Level 1 of the geometric amplitude: 0.430 mm (hand computation in PerceptionModelTest).
  EXPECT_TRUE(contains(result.out, "      1           4.317          4.302       0.430"))
      << result.out;
}

TEST_F(LevelsCliTest, TwentyMillimetreTableHasFewerGeometricLevels) {
  const auto result = run("levels --size-mm 20");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(contains(result.out, "geometric_amplitude: 3 levels")) << result.out;
  EXPECT_TRUE(contains(result.out, "colour_amplitude: 4 levels")) << result.out;
  EXPECT_TRUE(contains(result.out, "usable range 0.100 .. 0.780 mm")) << result.out;
}

TEST_F(LevelsCliTest, AVariableWithoutUsableRangeSaysSoAndTheOthersArePrinted) {
  const auto result = run("levels --size-mm 10");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(contains(result.out, "colour_frequency: a glyph of 10 mm leaves no usable"))
      << result.out;
  EXPECT_TRUE(contains(result.out, "colour_amplitude: 4 levels")) << result.out;
}

TEST_F(LevelsCliTest, BadArgumentsAreUsageErrorsAndABadModelFails) {
  for (const std::string args :
       {"levels --size-mm 0", "levels --size-mm nan", "levels --size-mm -3",
        "levels --waveform zigzag", "levels extra", "levels --bogus"}) {
    const auto result = run(args);
    EXPECT_EQ(result.exit_code, 2) << args;
    EXPECT_TRUE(contains(result.err, "usage: vicc_glyph levels")) << args << ": " << result.err;
  }
  const auto missing = run("levels --model /nonexistent/model.yaml");
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_TRUE(contains(missing.err, "/nonexistent/model.yaml")) << missing.err;
}
