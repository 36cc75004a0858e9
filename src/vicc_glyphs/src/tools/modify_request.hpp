#pragma once
// The parsed and validated arguments of "vicc_glyph modify" (modify_command.hpp).

#include <optional>
#include <string>
#include <vector>

#include "command_line.hpp"
#include "vicc_glyphs/pacemod/curve_selection.hpp"
#include "vicc_glyphs/pacemod/dashes.hpp"
#include "vicc_glyphs/pacemod/wave_spec.hpp"

namespace vicc_glyphs::tools {

struct ModifyRequest {
  std::string input;
  std::string output;
  std::string dci;     ///< empty: not written
  std::string report;  ///< empty: not written
  int size = 512;
  double size_mm = 50.0;
  pacemod::CurveSelection curves;
  std::optional<pacemod::WaveSpec> waves;
  std::optional<pacemod::DashSpec> dashes;
  std::optional<double> inflate_mm;
  bool help = false;
};

const std::vector<OptionSpec>& modifyOptions();

/// Throws UsageError naming the option for anything missing, malformed or out of range.
ModifyRequest parseModifyRequest(const std::vector<std::string>& args);

}  // namespace vicc_glyphs::tools
