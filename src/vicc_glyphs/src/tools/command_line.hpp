#pragma once
// vicc_glyph's subcommands parse their options with vicc_common's command-line parser, the
// one every VICC tool uses ("--name value", "--name=value", flags, "--", one UsageError).

#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "vicc_common/command_line.hpp"

namespace vicc_glyphs::tools {

using vicc_common::cli::formatOptions;
using vicc_common::cli::OptionSpec;
using vicc_common::cli::parseArguments;
using vicc_common::cli::ParsedArguments;
using vicc_common::cli::parseInteger;
using vicc_common::cli::parseNumber;
using vicc_common::cli::requireDistinctFiles;
using vicc_common::cli::UsageError;

/// Reads a subcommand's command line as every vicc_glyph subcommand does: parses `args` with
/// `options` and hands them to `read`, which takes the values it needs (and may throw
/// UsageError). --help prints `usage` to `out`: exit code 0. A usage error prints "vicc_glyph
/// NAME: <message>", a blank line and `usage` to `err`: exit code 2. Returns that exit code, or
/// nothing when the subcommand should go on.
inline std::optional<int> readCommandLine(const std::string& name,
                                          const std::vector<std::string>& args,
                                          const std::vector<OptionSpec>& options,
                                          void (*usage)(std::ostream&), std::ostream& out,
                                          std::ostream& err,
                                          const std::function<void(const ParsedArguments&)>& read) {
  try {
    const ParsedArguments parsed = parseArguments(args, options);
    if (parsed.has("help")) {
      usage(out);
      return 0;
    }
    read(parsed);
  } catch (const UsageError& e) {
    err << "vicc_glyph " << name << ": " << e.what() << "\n\n";
    usage(err);
    return 2;
  }
  return std::nullopt;
}

}  // namespace vicc_glyphs::tools
