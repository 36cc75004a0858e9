#pragma once
// Command-line parsing of vicc_patient: a command, file arguments, --options with values
// (also --option=value) and flags; anything unknown is a usage error. The parsing itself is
// vicc_common's command-line parser, the one every VICC tool uses.

#include <map>
#include <set>
#include <string>
#include <vector>

#include "vicc_common/command_line.hpp"

namespace vicc_anatomy_viz::cli {

using UsageError = vicc_common::cli::UsageError;

extern const std::set<std::string> kCommands;
/// Commands that only read: they open the database read-only and never create it.
extern const std::set<std::string> kReadCommands;

struct CommandLine {
  std::string command;
  std::vector<std::string> positional;
  std::map<std::string, std::string> options;
  std::set<std::string> flags;

  std::string option(const std::string& name, const std::string& fallback = "") const;
  /// UsageError naming the command when the option is missing.
  std::string required(const std::string& name) const;
  bool flag(const std::string& name) const { return flags.count(name) > 0; }
  /// A non-negative integer option; UsageError naming it otherwise.
  int integerOption(const std::string& name, int fallback) const;
  /// UsageError unless exactly `count` file arguments were given.
  void expectPositional(std::size_t count) const;
};

CommandLine parseCommandLine(const std::vector<std::string>& args);
/// "a,b,,c" -> {a, b, c}.
std::vector<std::string> splitList(const std::string& text);

}  // namespace vicc_anatomy_viz::cli
