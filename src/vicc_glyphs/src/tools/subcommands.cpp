#include "modify_command.hpp"
#include "render_command.hpp"
#include "subcommand.hpp"

namespace vicc_glyphs::tools {

const std::vector<Subcommand>& subcommands() {
  static const std::vector<Subcommand> table{
      {"render", "render a DCI, SVG icon or PNG to a PNG image", &runRenderCommand},
      {"modify", "PACEMOD waves, dashes, inflate on an icon; PNG + DCI + report", &runModifyCommand},
  };
  return table;
}

}  // namespace vicc_glyphs::tools
