#pragma once
// Option parsing shared by the vicc_glyph subcommands: "--name value", "--name=value" and
// flags, positional arguments, and errors that say what was wrong.

#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace vicc_glyphs::tools {

/// A command-line mistake: reported with the subcommand's usage and exit code 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct OptionSpec {
  std::string name;        ///< without the leading "--"
  std::string value_name;  ///< empty for a flag, else the placeholder shown in the help
  std::string help;
};

struct ParsedArguments {
  std::vector<std::string> positional;
  std::map<std::string, std::string> values;
  std::set<std::string> flags;

  bool has(const std::string& name) const { return values.count(name) || flags.count(name); }
  /// The option's value, or `fallback` if it was not given.
  std::string value(const std::string& name, const std::string& fallback = "") const;
};

/// Parses `args` against `specs`. Throws UsageError for unknown options, a missing value or a
/// value given to a flag. "--" ends the options.
ParsedArguments parseArguments(const std::vector<std::string>& args,
                               const std::vector<OptionSpec>& specs);

/// Parses `text` as an integer in [minimum, maximum]; throws UsageError naming `option`.
int parseInteger(const std::string& option, const std::string& text, int minimum, int maximum);

/// One line per option, aligned, for a subcommand's --help.
std::string formatOptions(const std::vector<OptionSpec>& specs);

}  // namespace vicc_glyphs::tools
