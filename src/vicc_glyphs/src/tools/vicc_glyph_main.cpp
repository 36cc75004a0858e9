// vicc_glyph: command-line tool for iconic glyphs; dispatches to the subcommand table.

#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "subcommand.hpp"

namespace {

void printOverview(std::ostream& out) {
  out << "usage: vicc_glyph SUBCOMMAND [ARGS...]   (vicc_glyph SUBCOMMAND --help for details)\n\n"
         "subcommands:\n";
  for (const vicc_glyphs::tools::Subcommand& command : vicc_glyphs::tools::subcommands()) {
    out << "  " << command.name << std::string(10 - std::min<size_t>(command.name.size(), 9), ' ')
        << command.summary << "\n";
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) {
    printOverview(std::cerr);
    return 2;
  }
  if (args.front() == "--help" || args.front() == "-h" || args.front() == "help") {
    printOverview(std::cout);
    return 0;
  }
  for (const vicc_glyphs::tools::Subcommand& command : vicc_glyphs::tools::subcommands()) {
    if (command.name == args.front()) {
      return command.run({args.begin() + 1, args.end()}, std::cout, std::cerr);
    }
  }
  std::cerr << "vicc_glyph: unknown subcommand '" << args.front() << "'\n\n";
  printOverview(std::cerr);
  return 2;
}
