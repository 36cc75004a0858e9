#pragma once
// vicc_glyph's subcommands parse their options with vicc_common's command-line parser, the
// one every VICC tool uses ("--name value", "--name=value", flags, "--", one UsageError).

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

}  // namespace vicc_glyphs::tools
