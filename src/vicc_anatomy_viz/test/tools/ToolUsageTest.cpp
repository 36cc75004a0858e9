// The avatar model tool and the bench tools parse their command lines with vicc_common's
// parser: an unknown option, a missing required option, a value of the wrong kind or out of
// range is a usage error (exit code 2) whose message names it, followed by the usage.
#include <gtest/gtest.h>

#include <string>

#include "expect_usage_error.hpp"

namespace {

using vicc_test::CommandResult;
using vicc_test::expectUsageError;

TEST(ToolUsage, AvatarModel) {
  expectUsageError(VICC_AVATAR_MODEL_TOOL, "", "--report or --export DIR is needed");
  expectUsageError(VICC_AVATAR_MODEL_TOOL, "--reprot", "--reprot");
  expectUsageError(VICC_AVATAR_MODEL_TOOL, "--report extra", "unexpected argument 'extra'");
  expectUsageError(VICC_AVATAR_MODEL_TOOL, "--export", "--export");
  const CommandResult help = vicc_test::runCommand(std::string(VICC_AVATAR_MODEL_TOOL) + " --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.output.find("--manifest FILE"), std::string::npos) << help.output;
}

TEST(ToolUsage, PatientBench) {
  expectUsageError(VICC_PATIENT_BENCH_TOOL, "--patient P", "needs --db");
  expectUsageError(VICC_PATIENT_BENCH_TOOL, "--db x.db", "needs --patient");
  expectUsageError(VICC_PATIENT_BENCH_TOOL, "--db x.db --patient P --repeat many", "--repeat");
  expectUsageError(VICC_PATIENT_BENCH_TOOL, "--db x.db --patient P --repaet 3", "--repaet");
}

TEST(ToolUsage, DurabilityBench) {
  expectUsageError(VICC_DURABILITY_BENCH_TOOL, "--records 10", "needs --dir");
  expectUsageError(VICC_DURABILITY_BENCH_TOOL, "--dir /tmp --records 0", "--records");
  expectUsageError(VICC_DURABILITY_BENCH_TOOL, "--dir /tmp --bulk lots", "--bulk");
  expectUsageError(VICC_DURABILITY_BENCH_TOOL, "--dir /tmp --repeats 3", "--repeats");
}

TEST(ToolUsage, AvatarFps) {
  // Usage errors come before any X server or rviz is started.
  expectUsageError(VICC_AVATAR_FPS_TOOL, "--patient P", "needs --db");
  expectUsageError(VICC_AVATAR_FPS_TOOL, "--db x.db --patient P --size 10x10", "--size");
  expectUsageError(VICC_AVATAR_FPS_TOOL, "--db x.db --patient P --frames 0", "--frames");
  expectUsageError(VICC_AVATAR_FPS_TOOL, "--db x.db --patient P --fulll", "--fulll");
}

}  // namespace
