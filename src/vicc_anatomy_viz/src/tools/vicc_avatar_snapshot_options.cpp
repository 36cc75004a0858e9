#include "vicc_avatar_snapshot_options.hpp"

#include <algorithm>
#include <regex>
#include <sstream>

#include "vicc_common/command_line.hpp"

namespace vicc_anatomy_viz::snapshot {

const char* const kSnapshotUsage =
    "usage: vicc_avatar_snapshot --db FILE --patient ID [--date D] "
    "[--view front|back|left|right] [--hide CAT,...] [--size WxH] --out FILE.png\n"
    "exit: 0 written, 2 bad command line, 3 unknown patient / date before the first "
    "examination / unreadable database, 4 no display server, 5 rendering failed, 6 written "
    "but incomplete (an encoded finding could not be drawn)";

namespace {

namespace cli = vicc_common::cli;

constexpr int kMinSide = 64, kMaxSide = 8192;

const std::vector<cli::OptionSpec> kOptionSpecs = {
    {"db", "FILE", ""},      {"patient", "ID", ""}, {"date", "D", ""},       {"view", "VIEW", ""},
    {"hide", "CAT,...", ""}, {"size", "WxH", ""},   {"out", "FILE.png", ""},
};

/// The value of a required option; the message shows its placeholder ("--db FILE").
std::string requiredValue(const cli::ParsedArguments& parsed, const std::string& name) {
  const std::string value = parsed.value(name);
  if (value.empty()) {
    const auto spec = std::find_if(kOptionSpecs.begin(), kOptionSpecs.end(),
                                   [&](const cli::OptionSpec& s) { return s.name == name; });
    throw cli::UsageError("--" + name + " " + spec->value_name + " is required");
  }
  return value;
}

std::vector<std::string> splitCategories(const std::string& text) {
  std::vector<std::string> categories;
  std::istringstream stream(text);
  std::string category;
  while (std::getline(stream, category, ','))
    if (!category.empty()) categories.push_back(category);
  return categories;
}

}  // namespace

void parseWindowSize(const std::string& text, int& width, int& height) {
  std::smatch match;
  if (!std::regex_match(text, match, std::regex("([0-9]{1,5})x([0-9]{1,5})")))
    throw cli::UsageError("--size: expected WxH, e.g. 800x1000, got '" + text + "'");
  width = std::stoi(match[1]);
  height = std::stoi(match[2]);
  for (int side : {width, height})
    if (side < kMinSide || side > kMaxSide)
      throw cli::UsageError("--size: each side must be " + std::to_string(kMinSide) + ".." +
                            std::to_string(kMaxSide) + " pixels, got '" + text + "'");
}

SnapshotOptions parseSnapshotOptions(const std::vector<std::string>& args) {
  const cli::ParsedArguments parsed = cli::parseArguments(args, kOptionSpecs);
  if (!parsed.positional.empty()) {
    throw cli::UsageError("unexpected argument '" + parsed.positional.front() + "'");
  }
  SnapshotOptions options;
  options.db = requiredValue(parsed, "db");
  options.patient = requiredValue(parsed, "patient");
  options.out = requiredValue(parsed, "out");
  options.date = parsed.value("date");
  options.hidden_categories = splitCategories(parsed.value("hide"));
  if (parsed.has("size")) parseWindowSize(parsed.value("size"), options.width, options.height);
  if (parsed.has("view")) {
    const std::string value = parsed.value("view");
    const auto view = avatar_view::bodyViewFromString(value);
    if (!view) throw cli::UsageError("--view: front, back, left or right, got '" + value + "'");
    options.view = *view;
  }
  return options;
}

}  // namespace vicc_anatomy_viz::snapshot
