#pragma once
// Shared by the tests that run a tool or a shell command: its output (stdout and stderr
// together, in order) and its exit code.

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace vicc_test {

struct CommandResult {
  int exit_code = -1;  ///< -1: the command could not be started or did not exit normally
  std::string output;  ///< stdout and stderr together
};

/// Runs `command` with /bin/sh, stderr merged into stdout.
inline CommandResult runCommand(const std::string& command) {
  CommandResult result;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer{};
  std::size_t read = 0;
  while ((read = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) {
    result.output.append(buffer.data(), read);
  }
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

}  // namespace vicc_test
