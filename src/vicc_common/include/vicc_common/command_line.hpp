#pragma once
// The command-line parser of every VICC tool: options declared once (name, value placeholder,
// help), "--name value", "--name=value" and flags, positional arguments, "--" ends the
// options, typed getters with ranges. Every mistake is one UsageError whose message says what
// was wrong; tools print it with their usage and exit with 2.

#include <functional>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace vicc_common::cli {

/// A bad argument of the command line (a std::invalid_argument, so code that reports bad
/// arguments reports it too); tools catch it first to print their usage.
struct UsageError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

struct OptionSpec {
  std::string name;        ///< without the leading "--"
  std::string value_name;  ///< empty for a flag, else the placeholder shown in the help
  std::string help;
  /// Whether the option may be given more than once (ParsedArguments::all has every value).
  /// Any other option given twice is a UsageError: taking the last value would silently
  /// change what a command does (another patient, another design value).
  bool repeatable = false;
};

struct ParsedArguments {
  std::vector<std::string> positional;
  std::map<std::string, std::string> values;  ///< each option's value (repeatable: the last)
  std::map<std::string, std::vector<std::string>> all_values;  ///< every value, in order
  std::set<std::string> flags;

  bool has(const std::string& name) const { return values.count(name) || flags.count(name); }
  bool flag(const std::string& name) const { return flags.count(name) > 0; }
  /// The option's value, or `fallback` if it was not given.
  std::string value(const std::string& name, const std::string& fallback = "") const;
  /// Every value of a repeatable option in the order given; empty if it was not given.
  std::vector<std::string> all(const std::string& name) const;
  /// The option's value; UsageError "<context> needs --<name>" if it is missing or empty.
  std::string required(const std::string& name, const std::string& context) const;
  /// An integer option in [minimum, maximum], `fallback` if not given; UsageError otherwise.
  int integer(const std::string& name, int fallback, int minimum, int maximum) const;
  /// A finite number in [minimum, maximum], `fallback` if not given; UsageError otherwise.
  double number(const std::string& name, double fallback, double minimum, double maximum) const;
};

/// Parses `args` against `specs`. Throws UsageError for an unknown option, a missing value, a
/// value given to a flag or an option given twice that is not repeatable. A single '-' and anything
/// not starting with '-' is positional.
ParsedArguments parseArguments(const std::vector<std::string>& args,
                               const std::vector<OptionSpec>& specs);

/// `text` as an integer in [minimum, maximum]; UsageError naming `option` otherwise.
int parseInteger(const std::string& option, const std::string& text, int minimum, int maximum);
/// `text` as a finite number in [minimum, maximum]; UsageError naming `option` otherwise.
double parseNumber(const std::string& option, const std::string& text, double minimum,
                   double maximum);

/// Throws UsageError naming both options when two of `files` (option name, path; empty paths
/// ignored) are the same file, existing or not: an output would overwrite an input or another
/// output.
void requireDistinctFiles(const std::vector<std::pair<std::string, std::string>>& files);

/// One line per option, aligned, for --help.
std::string formatOptions(const std::vector<OptionSpec>& specs);

/// "usage: <synopsis>\n<description>\noptions:\n<formatOptions>".
std::string helpText(const std::string& synopsis, const std::string& description,
                     const std::vector<OptionSpec>& specs);

/// The main() of a tool: "--help" or "-h" alone prints `usage` (exit 0); otherwise `run` gets
/// the arguments and its result is the exit code. A UsageError prints "<tool>: <what>" and the
/// usage to stderr (exit 2), any other exception "<tool>: <what>" (exit 1).
int runTool(const std::string& tool, int argc, char** argv, const std::string& usage,
            const std::function<int(const std::vector<std::string>&)>& run);

}  // namespace vicc_common::cli
