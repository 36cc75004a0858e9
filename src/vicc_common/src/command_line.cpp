#include "vicc_common/command_line.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace vicc_common::cli {
namespace {

const OptionSpec* findSpec(const std::vector<OptionSpec>& specs, const std::string& name) {
  const auto found = std::find_if(specs.begin(), specs.end(),
                                  [&](const OptionSpec& spec) { return spec.name == name; });
  return found == specs.end() ? nullptr : &*found;
}

bool isOption(const std::string& arg) { return arg.size() > 1 && arg[0] == '-'; }

/// std::stol/stod skip leading blanks; a value on the command line must not start with one.
bool startsWithBlank(const std::string& text) {
  return !text.empty() && std::isspace(static_cast<unsigned char>(text[0]));
}

std::string rangeText(double minimum, double maximum) {
  std::ostringstream text;
  text << minimum << " to " << maximum;
  return text.str();
}

}  // namespace

std::string ParsedArguments::value(const std::string& name, const std::string& fallback) const {
  const auto found = values.find(name);
  return found == values.end() ? fallback : found->second;
}

std::vector<std::string> ParsedArguments::all(const std::string& name) const {
  const auto found = all_values.find(name);
  return found == all_values.end() ? std::vector<std::string>{} : found->second;
}

std::string ParsedArguments::required(const std::string& name, const std::string& context) const {
  const auto found = values.find(name);
  if (found == values.end() || found->second.empty()) {
    throw UsageError(context + " needs --" + name);
  }
  return found->second;
}

int ParsedArguments::integer(const std::string& name, int fallback, int minimum,
                             int maximum) const {
  const auto found = values.find(name);
  return found == values.end() ? fallback : parseInteger(name, found->second, minimum, maximum);
}

double ParsedArguments::number(const std::string& name, double fallback, double minimum,
                               double maximum) const {
  const auto found = values.find(name);
  return found == values.end() ? fallback : parseNumber(name, found->second, minimum, maximum);
}

ParsedArguments parseArguments(const std::vector<std::string>& args,
                               const std::vector<OptionSpec>& specs) {
  ParsedArguments parsed;
  bool options_ended = false;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (options_ended || !isOption(arg)) {
      parsed.positional.push_back(arg);
      continue;
    }
    if (arg == "--") {
      options_ended = true;
      continue;
    }
    if (arg.compare(0, 2, "--") != 0) {
      throw UsageError("unknown option '" + arg + "' (options start with --)");
    }
    const size_t equals = arg.find('=');
    const std::string name =
        arg.substr(2, equals == std::string::npos ? std::string::npos : equals - 2);
    const OptionSpec* spec = findSpec(specs, name);
    if (!spec) throw UsageError("unknown option '--" + name + "'");
    if (spec->value_name.empty()) {
      if (equals != std::string::npos) throw UsageError("option '--" + name + "' takes no value");
      parsed.flags.insert(name);
    } else {
      if (equals == std::string::npos && i + 1 >= args.size()) {
        throw UsageError("option '--" + name + "' needs a value " + spec->value_name);
      }
      const std::string value = equals != std::string::npos ? arg.substr(equals + 1) : args[++i];
      if (!spec->repeatable && parsed.values.count(name)) {
        throw UsageError("option '--" + name + "' is given more than once");
      }
      parsed.values[name] = value;
      parsed.all_values[name].push_back(value);
    }
  }
  return parsed;
}

void requireDistinctFiles(const std::vector<std::pair<std::string, std::string>>& files) {
  std::vector<std::filesystem::path> resolved;
  for (const auto& file : files) {
    // Absolute and normal first: weakly_canonical leaves ".." after a missing directory.
    std::error_code error;
    const std::filesystem::path normal =
        std::filesystem::absolute(file.second, error).lexically_normal();
    const std::filesystem::path path = std::filesystem::weakly_canonical(normal, error);
    resolved.push_back(error ? normal : path);
  }
  for (size_t i = 0; i < files.size(); ++i) {
    for (size_t j = i + 1; j < files.size(); ++j) {
      if (files[i].second.empty() || files[j].second.empty() || resolved[i] != resolved[j]) {
        continue;
      }
      throw UsageError(files[i].first + " and " + files[j].first + " are the same file (" +
                       files[j].second + "): one would overwrite the other");
    }
  }
}

int parseInteger(const std::string& option, const std::string& text, int minimum, int maximum) {
  size_t used = 0;
  long value = 0;
  try {
    value = std::stol(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || startsWithBlank(text) || value < minimum ||
      value > maximum) {
    throw UsageError("option '--" + option + "' needs an integer from " + std::to_string(minimum) +
                     " to " + std::to_string(maximum) + ", got '" + text + "'");
  }
  return static_cast<int>(value);
}

double parseNumber(const std::string& option, const std::string& text, double minimum,
                   double maximum) {
  size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || startsWithBlank(text) || !std::isfinite(value) ||
      value < minimum || value > maximum) {
    throw UsageError("option '--" + option + "' needs a number from " +
                     rangeText(minimum, maximum) + ", got '" + text + "'");
  }
  return value;
}

std::string formatOptions(const std::vector<OptionSpec>& specs) {
  std::vector<std::string> heads;
  size_t width = 0;
  for (const OptionSpec& spec : specs) {
    heads.push_back("--" + spec.name + (spec.value_name.empty() ? "" : " " + spec.value_name));
    width = std::max(width, heads.back().size());
  }
  std::ostringstream text;
  for (size_t i = 0; i < specs.size(); ++i) {
    text << "  " << heads[i] << std::string(width - heads[i].size() + 2, ' ') << specs[i].help
         << "\n";
  }
  return text.str();
}

std::string helpText(const std::string& synopsis, const std::string& description,
                     const std::vector<OptionSpec>& specs) {
  std::string text = "usage: " + synopsis + "\n";
  if (!description.empty()) text += description + (description.back() == '\n' ? "" : "\n");
  if (!specs.empty()) text += "options:\n" + formatOptions(specs);
  return text;
}

int runTool(const std::string& tool, int argc, char** argv, const std::string& usage,
            const std::function<int(const std::vector<std::string>&)>& run) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.size() == 1 && (args[0] == "--help" || args[0] == "-h")) {
    std::cout << usage;
    return 0;
  }
  try {
    return run(args);
  } catch (const UsageError& error) {
    std::cerr << tool << ": " << error.what() << "\n" << usage;
    return 2;
  } catch (const std::exception& error) {
    std::cerr << tool << ": " << error.what() << "\n";
    return 1;
  }
}

}  // namespace vicc_common::cli
