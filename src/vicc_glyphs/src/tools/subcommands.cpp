#include "check_design_command.hpp"
#include "design_command.hpp"
#include "design_map_command.hpp"
#include "fit_command.hpp"
#include "levels_command.hpp"
#include "modify_command.hpp"
#include "render_command.hpp"
#include "subcommand.hpp"

namespace vicc_glyphs::tools {

const std::vector<Subcommand>& subcommands() {
  static const std::vector<Subcommand> table{
      {"render", "render a DCI, SVG icon or PNG to a PNG image", &runRenderCommand},
      {"levels", "level-to-stimulus table of the perception model", &runLevelsCommand},
      {"design", "render a glyph design (YAML) for data values", &runDesignCommand},
      {"design-map", "one glyph per table row, placed by lon/lat, on one PNG",
       &runDesignMapCommand},
      {"check-design", "build every level combination of a design; list those that fail",
       &runCheckDesignCommand},
      {"fit-model", "fit the perception model to survey answers (CSV)", &runFitCommand},
      {"modify", "PACEMOD waves, dashes, inflate on an icon; PNG + DCI + report",
       &runModifyCommand},
  };
  return table;
}

}  // namespace vicc_glyphs::tools
