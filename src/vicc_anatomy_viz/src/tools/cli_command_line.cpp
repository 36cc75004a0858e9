#include "cli_command_line.hpp"

#include <sstream>

namespace vicc_anatomy_viz::cli {

const std::set<std::string> kCommands = {"init",    "import", "export", "list",  "dates",
                                         "show",    "encode", "record", "check", "config",
                                         "history", "backup", "restore"};
const std::set<std::string> kReadCommands = {"export", "list",  "dates",   "show",
                                             "encode", "check", "history", "backup"};

namespace {
const std::set<std::string> kFlags = {"--json",         "--replace", "--replace-with-empty",
                                      "--skip-unknown", "--help",    "-h"};
const std::set<std::string> kOptions = {
    "--db",     "--config", "--anatomy", "--view",         "--patient",      "--date",
    "--format", "--out",    "--hide",    "--busy-timeout", "--group-window", "--max-future"};
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
  try {
    std::size_t used = 0;
    const int value = std::stoi(it->second, &used);
    if (used != it->second.size() || value < 0) throw std::invalid_argument(it->second);
    return value;
  } catch (const std::exception&) {
    throw UsageError(name + " needs a non-negative whole number, not '" + it->second + "'");
  }
}

void CommandLine::expectPositional(std::size_t count) const {
  if (positional.size() != count) {
    throw UsageError(command + " takes " + std::to_string(count) + " file argument" +
                     (count == 1 ? "" : "s"));
  }
}

CommandLine parseCommandLine(const std::vector<std::string>& args) {
  CommandLine line;
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string arg = args[i];
    std::string value;
    bool has_value = false;
    if (arg.rfind("--", 0) == 0 && arg.find('=') != std::string::npos) {
      value = arg.substr(arg.find('=') + 1);
      arg = arg.substr(0, arg.find('='));
      has_value = true;
    }
    if (kFlags.count(arg)) {
      if (has_value) throw UsageError(arg + " takes no value");
      line.flags.insert(arg);
    } else if (kOptions.count(arg)) {
      if (!has_value) {
        if (i + 1 >= args.size()) throw UsageError(arg + " needs a value");
        value = args[++i];
      }
      line.options[arg] = value;
    } else if (arg.size() > 1 && arg[0] == '-') {
      throw UsageError("unknown option " + arg);
    } else if (line.command.empty()) {
      line.command = arg;
    } else {
      line.positional.push_back(arg);
    }
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
