// The glyph bench tools parse their command lines with vicc_common's parser: a bad option is
// a usage error (exit code 2) naming it, followed by the usage; --help prints the usage.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "expect_usage_error.hpp"

namespace {

using vicc_test::expectUsageError;

TEST(BenchUsage, GlyphBench) {
  expectUsageError(VICC_GLYPH_BENCH_BINARY, "", "no input given");
  expectUsageError(VICC_GLYPH_BENCH_BINARY, "--size abc x.svg", "--size");
  expectUsageError(VICC_GLYPH_BENCH_BINARY, "--tolerance 2 x.svg", "--tolerance");
  expectUsageError(VICC_GLYPH_BENCH_BINARY, "--repeat 3 x.svg", "--repeat");
  const vicc_test::CommandResult help =
      vicc_test::runCommand(std::string(VICC_GLYPH_BENCH_BINARY) + " --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.output.find("--tolerance E"), std::string::npos) << help.output;
}

TEST(BenchUsage, ConvergenceHistory) {
  expectUsageError(VICC_GLYPH_CONVERGENCE_BINARY, "", "no input given");
  expectUsageError(VICC_GLYPH_CONVERGENCE_BINARY, "--iterations 0 x.svg", "--iterations");
}

// The solver stops a fixed-count run once its correction is below float resolution; the table
// ends there (it printed rows read past the end of the recorded history: 1.00e+00, 4.6e-310).
TEST(BenchUsage, ConvergenceHistoryEndsWhereTheSolverStopped) {
  const vicc_test::CommandResult run = vicc_test::runCommand(
      std::string(VICC_GLYPH_CONVERGENCE_BINARY) + " --size 64 --iterations 40 " +
      VICC_GLYPHS_DATA_DIR + "/icons/bell.svg");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("| 0 | "), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("| 40 | "), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("(asked for 40 iterations; the solver stopped after "),
            std::string::npos)
      << run.output;
  for (const char* garbage : {"e-30", "e-31", "e-32", "e+00 |"}) {  // denormals, 1.00e+00
    EXPECT_EQ(run.output.find(garbage), std::string::npos) << garbage << "\n" << run.output;
  }
}

TEST(BenchUsage, StrokeBench) {
  expectUsageError(VICC_GLYPHS_STROKE_BENCH_BINARY, "--repeats 0", "--repeats");
  expectUsageError(VICC_GLYPHS_STROKE_BENCH_BINARY, "x.svg", "no positional arguments");
  // One outline per case: the table has a row per case and outliner.
  const vicc_test::CommandResult table =
      vicc_test::runCommand(std::string(VICC_GLYPHS_STROKE_BENCH_BINARY) + " --repeats 1");
  EXPECT_EQ(table.exit_code, 0) << table.output;
  EXPECT_NE(table.output.find("| u-turn | 16.0 | curves | "), std::string::npos) << table.output;
  EXPECT_NE(table.output.find("| icon-arc | 21.3 | clipper | "), std::string::npos) << table.output;
}

TEST(BenchUsage, FeatureTransformBench) {
  expectUsageError(VICC_GLYPHS_FEATURE_TRANSFORM_BENCH_BINARY, "/nonexistent/icons",
                   "no directory /nonexistent/icons");
  expectUsageError(VICC_GLYPHS_FEATURE_TRANSFORM_BENCH_BINARY, "a b", "more than one ICON_DIR");
  expectUsageError(VICC_GLYPHS_FEATURE_TRANSFORM_BENCH_BINARY, "--grid 3", "--grid");
}

#ifdef VICC_GLYPHS_PACEMOD_BENCH_BINARY  // built with the PACEMOD part (pacemod.cmake)
// The bench says which malloc settings its times were taken with: those of the glyph server's
// process unless --default-heap.
TEST(BenchUsage, PacemodBenchSaysWhichHeapItMeasuresWith) {
  expectUsageError(VICC_GLYPHS_PACEMOD_BENCH_BINARY, "--waveform square", "--waveform");
  const std::string one_glyph = std::string(VICC_GLYPHS_PACEMOD_BENCH_BINARY) +
                                " --icon bell.svg --waveform sine --frequency 2 --amplitude 0.4"
                                " --no-render";
  const vicc_test::CommandResult server = vicc_test::runCommand(one_glyph);
  EXPECT_EQ(server.exit_code, 0) << server.output;
  EXPECT_NE(server.output.find("heap: freed memory kept for reuse, as in glyph_server"),
            std::string::npos)
      << server.output;
  EXPECT_NE(server.output.find("| sine, 2, 0.4 | 1 |"), std::string::npos) << server.output;
  const vicc_test::CommandResult plain = vicc_test::runCommand(one_glyph + " --default-heap");
  EXPECT_EQ(plain.exit_code, 0) << plain.output;
  EXPECT_NE(plain.output.find("heap: glibc defaults (--default-heap)"), std::string::npos)
      << plain.output;
}

// --repeats N makes each glyph N times and writes one line of times per glyph (the fastest run).
TEST(BenchUsage, PacemodBenchRepeatsEachGlyphAndKeepsOneLineOfTimes) {
  expectUsageError(VICC_GLYPHS_PACEMOD_BENCH_BINARY, "--repeats 0", "--repeats");
  expectUsageError(VICC_GLYPHS_PACEMOD_BENCH_BINARY, "--repeats 1.5", "--repeats");
  const std::string times = ::testing::TempDir() + "pacemod_bench_repeats.tsv";
  const vicc_test::CommandResult run = vicc_test::runCommand(
      std::string(VICC_GLYPHS_PACEMOD_BENCH_BINARY) +
      " --icon bell.svg --waveform sine --frequency 2 --amplitude 0.4 --repeats 2 --times " +
      times);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("times of the fastest of 2 run(s) per glyph"), std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("| sine, 2, 0.4 | 1 |"), std::string::npos) << run.output;
  std::ifstream file(times);
  std::vector<std::string> lines;
  for (std::string line; std::getline(file, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 2u);  // the header and the one glyph
  EXPECT_EQ(lines[1].rfind("bell.svg\tsine\t2\t0.4\t", 0), 0u) << lines[1];
}
#endif

#ifdef VICC_GLYPHS_DESIGN_BENCH_BINARY  // built with the design part (design.cmake)
// The design bench's --repeats: the same rule; one line of times per level combination.
TEST(BenchUsage, DesignBenchRepeatsEachGlyphAndKeepsOneLineOfTimes) {
  expectUsageError(VICC_GLYPHS_DESIGN_BENCH_BINARY, "--repeats 0", "--repeats");
  const std::string times = ::testing::TempDir() + "design_bench_repeats.tsv";
  const vicc_test::CommandResult run =
      vicc_test::runCommand(std::string(VICC_GLYPHS_DESIGN_BENCH_BINARY) +
                            " " VICC_GLYPHS_DESIGNS_DIR "/intracranial_pressure.yaml" +
                            " --size 64 --repeats 2 --times " + times);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("times of the fastest of 2 run(s) per glyph"), std::string::npos)
      << run.output;
  std::ifstream file(times);
  int lines = 0;
  for (std::string line; std::getline(file, line);) ++lines;
  EXPECT_EQ(lines, 1 + 21);  // the header and the intracranial pressure design's 21 glyphs
}
#endif

}  // namespace
