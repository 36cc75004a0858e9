#pragma once
// Shared by the tests of the tools' command lines (vicc_common_cli): a bad command line is a
// usage error with exit code 2, a message naming what is wrong, and the usage.

#include <gtest/gtest.h>

#include <string>

#include "run_command.hpp"

namespace vicc_test {

/// `tool arguments` exits with 2 and prints `expected` and the usage.
inline void expectUsageError(const std::string& tool, const std::string& arguments,
                             const std::string& expected) {
  const CommandResult result = runCommand(tool + " " + arguments);
  EXPECT_EQ(result.exit_code, 2) << arguments << ":\n" << result.output;
  EXPECT_NE(result.output.find(expected), std::string::npos) << arguments << ":\n" << result.output;
  EXPECT_NE(result.output.find("usage: "), std::string::npos) << result.output;
}

}  // namespace vicc_test
