#include "command_line.hpp"

#include <algorithm>
#include <sstream>

namespace vicc_glyphs::tools {
namespace {

const OptionSpec* findSpec(const std::vector<OptionSpec>& specs, const std::string& name) {
  const auto found = std::find_if(specs.begin(), specs.end(),
                                  [&](const OptionSpec& spec) { return spec.name == name; });
  return found == specs.end() ? nullptr : &*found;
}

}  // namespace

std::string ParsedArguments::value(const std::string& name, const std::string& fallback) const {
  const auto found = values.find(name);
  return found == values.end() ? fallback : found->second;
}

ParsedArguments parseArguments(const std::vector<std::string>& args,
                               const std::vector<OptionSpec>& specs) {
  ParsedArguments parsed;
  bool options_ended = false;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (options_ended || arg.size() < 2 || arg.compare(0, 2, "--") != 0) {
      if (!options_ended && arg.size() > 1 && arg[0] == '-' && arg != "-") {
        throw UsageError("unknown option '" + arg + "' (options start with --)");
      }
      parsed.positional.push_back(arg);
      continue;
    }
    if (arg == "--") {
      options_ended = true;
      continue;
    }
    const size_t equals = arg.find('=');
    const std::string name =
        arg.substr(2, equals == std::string::npos ? std::string::npos : equals - 2);
    const OptionSpec* spec = findSpec(specs, name);
    if (!spec) throw UsageError("unknown option '--" + name + "'");
    if (spec->value_name.empty()) {
      if (equals != std::string::npos) throw UsageError("option '--" + name + "' takes no value");
      parsed.flags.insert(name);
    } else if (equals != std::string::npos) {
      parsed.values[name] = arg.substr(equals + 1);
    } else if (i + 1 < args.size()) {
      parsed.values[name] = args[++i];
    } else {
      throw UsageError("option '--" + name + "' needs a value " + spec->value_name);
    }
  }
  return parsed;
}

int parseInteger(const std::string& option, const std::string& text, int minimum, int maximum) {
  size_t used = 0;
  long value = 0;
  try {
    value = std::stol(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || value < minimum || value > maximum) {
    throw UsageError("option '--" + option + "' needs an integer from " + std::to_string(minimum) +
                     " to " + std::to_string(maximum) + ", got '" + text + "'");
  }
  return static_cast<int>(value);
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

}  // namespace vicc_glyphs::tools
