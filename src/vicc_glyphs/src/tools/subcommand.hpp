#pragma once
// The vicc_glyph subcommand table: one entry (and one source file) per subcommand.

#include <ostream>
#include <string>
#include <vector>

namespace vicc_glyphs::tools {

struct Subcommand {
  std::string name;
  std::string summary;  ///< one line for the tool's overview
  /// Runs with the arguments after the subcommand name; returns the process exit code
  /// (0 success, 1 failure on valid input, 2 usage error).
  int (*run)(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
};

/// All subcommands, in the order the overview lists them.
const std::vector<Subcommand>& subcommands();

}  // namespace vicc_glyphs::tools
