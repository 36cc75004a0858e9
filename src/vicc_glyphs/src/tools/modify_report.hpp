#pragma once
// The JSON report of "vicc_glyph modify": what was applied to which curve.

#include <nlohmann/json.hpp>
#include <vector>

#include "modify_request.hpp"
#include "vicc_glyphs/pacemod/dashes.hpp"
#include "vicc_glyphs/pacemod/inflate.hpp"
#include "vicc_glyphs/pacemod/periodic_waves.hpp"

namespace vicc_glyphs::tools {

struct ModifyOutcome {
  std::vector<int> selected;
  std::vector<pacemod::CurveInflateReport> inflated;
  std::vector<pacemod::CurveWaveReport> waves;
  std::vector<pacemod::CurveDashReport> dashes;
  int curve_count = 0;
  double render_ms = 0.0;
};

nlohmann::json modifyReportJson(const ModifyRequest& request, const ModifyOutcome& outcome);

}  // namespace vicc_glyphs::tools
