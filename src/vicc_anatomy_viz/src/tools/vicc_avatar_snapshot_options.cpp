#include "vicc_avatar_snapshot_options.hpp"

#include <regex>
#include <sstream>
#include <stdexcept>

namespace vicc_anatomy_viz::snapshot {

const char* const kSnapshotUsage =
    "usage: vicc_avatar_snapshot --db FILE --patient ID [--date D] "
    "[--view front|back|left|right] [--hide CAT,...] [--size WxH] --out FILE.png\n"
    "exit: 0 written, 2 bad command line, 3 unknown patient / date before the first "
    "examination / unreadable database, 4 no display server, 5 rendering failed, 6 written "
    "but incomplete (an encoded finding could not be drawn)";

namespace {

constexpr int kMinSide = 64, kMaxSide = 8192;

void readSize(const std::string& text, SnapshotOptions& options) {
  std::smatch match;
  if (!std::regex_match(text, match, std::regex("([0-9]{1,5})x([0-9]{1,5})")))
    throw std::invalid_argument("--size: expected WxH, e.g. 800x1000, got '" + text + "'");
  options.width = std::stoi(match[1]);
  options.height = std::stoi(match[2]);
  for (int side : {options.width, options.height})
    if (side < kMinSide || side > kMaxSide)
      throw std::invalid_argument("--size: each side must be " + std::to_string(kMinSide) + ".." +
                                  std::to_string(kMaxSide) + " pixels, got '" + text + "'");
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

SnapshotOptions parseSnapshotOptions(const std::vector<std::string>& args) {
  SnapshotOptions options;
  bool has_db = false, has_patient = false, has_out = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& option = args[i];
    if (i + 1 >= args.size()) throw std::invalid_argument(option + ": missing value");
    const std::string& value = args[++i];
    if (option == "--db")
      options.db = value, has_db = true;
    else if (option == "--patient")
      options.patient = value, has_patient = true;
    else if (option == "--date")
      options.date = value;
    else if (option == "--out")
      options.out = value, has_out = true;
    else if (option == "--hide")
      options.hidden_categories = splitCategories(value);
    else if (option == "--size")
      readSize(value, options);
    else if (option == "--view") {
      const auto view = avatar_view::bodyViewFromString(value);
      if (!view)
        throw std::invalid_argument("--view: front, back, left or right, got '" + value + "'");
      options.view = *view;
    } else {
      throw std::invalid_argument("unknown option '" + option + "'");
    }
  }
  if (!has_db || options.db.empty()) throw std::invalid_argument("--db FILE is required");
  if (!has_patient || options.patient.empty())
    throw std::invalid_argument("--patient ID is required");
  if (!has_out || options.out.empty()) throw std::invalid_argument("--out FILE.png is required");
  return options;
}

}  // namespace vicc_anatomy_viz::snapshot
