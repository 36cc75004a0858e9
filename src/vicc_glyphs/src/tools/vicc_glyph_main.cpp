// vicc_glyph: command-line tool for iconic glyphs; dispatches to the subcommand table.

#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "subcommand.hpp"
#include "vicc_glyphs/render/process_heap.hpp"

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
  // The process is the tool's own, and check-design and design-map make glyph after glyph:
  // without this, every glyph's large buffers came as fresh pages (check-design of the COVID-19
  // design at 192 px: 7.6 s, 287,000 page faults; with it 4.8 s, 1,600). Where the C library
  // refuses, the tool only runs slower: nothing to report.
  vicc_glyphs::keepFreedMemoryForReuse();
  for (const vicc_glyphs::tools::Subcommand& command : vicc_glyphs::tools::subcommands()) {
    if (command.name == args.front()) {
      return command.run({args.begin() + 1, args.end()}, std::cout, std::cerr);
    }
  }
  std::cerr << "vicc_glyph: unknown subcommand '" << args.front() << "'\n\n";
  printOverview(std::cerr);
  return 2;
}
