#include "cli_command_line.hpp"

#include <limits>
#include <sstream>

namespace vicc_anatomy_viz::cli {

const std::set<std::string> kCommands = {"init",    "import", "export", "list",  "dates",
                                         "show",    "encode", "record", "check", "config",
                                         "history", "backup", "restore"};
const std::set<std::string> kReadCommands = {"export", "list",  "dates",   "show",
                                             "encode", "check", "history", "backup"};

namespace {
const std::set<std::string> kFlags = {"json", "replace", "replace-with-empty", "skip-unknown",
                                      "help"};
const std::set<std::string> kOptions = {"db",      "config",       "anatomy",      "view",
                                        "patient", "date",         "format",       "out",
                                        "hide",    "busy-timeout", "group-window", "max-future"};

std::vector<vicc_common::cli::OptionSpec> optionSpecs() {
  std::vector<vicc_common::cli::OptionSpec> specs;
  for (const std::string& name : kFlags) specs.push_back({name, "", ""});
  for (const std::string& name : kOptions) specs.push_back({name, "VALUE", ""});
  return specs;
}
}  // namespace

std::string CommandLine::option(const std::string& name, const std::string& fallback) const {
  const auto it = options.find(name);
  return it == options.end() ? fallback : it->second;
}

std::string CommandLine::required(const std::string& name) const {
  const auto it = options.find(name);
  if (it == options.end() || it->second.empty()) throw UsageError(command + " needs " + name);
  return it->second;
}

int CommandLine::integerOption(const std::string& name, int fallback) const {
  const auto it = options.find(name);
  if (it == options.end()) return fallback;
  return vicc_common::cli::parseInteger(name.substr(2), it->second, 0,
                                        std::numeric_limits<int>::max());
}

void CommandLine::expectPositional(std::size_t count) const {
  if (positional.size() != count) {
    throw UsageError(command + " takes " + std::to_string(count) + " file argument" +
                     (count == 1 ? "" : "s"));
  }
}

CommandLine parseCommandLine(const std::vector<std::string>& args) {
  // "-h" is the one short option; the rest is the common parser's.
  std::vector<std::string> long_form = args;
  for (std::string& arg : long_form) {
    if (arg == "-h") arg = "--help";
  }
  const vicc_common::cli::ParsedArguments parsed =
      vicc_common::cli::parseArguments(long_form, optionSpecs());
  CommandLine line;
  for (const auto& [name, value] : parsed.values) line.options["--" + name] = value;
  for (const std::string& name : parsed.flags) line.flags.insert("--" + name);
  if (!parsed.positional.empty()) {
    line.command = parsed.positional.front();
    line.positional.assign(parsed.positional.begin() + 1, parsed.positional.end());
  }
  return line;
}

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    if (!item.empty()) items.push_back(item);
  }
  return items;
}

}  // namespace vicc_anatomy_viz::cli
