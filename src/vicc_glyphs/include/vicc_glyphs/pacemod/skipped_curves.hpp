#pragma once
// A modification that no curve took: every curve's report (waves, dashes, inflation) says why
// it was skipped. The glyph then looks unmodified and reads as another level (no waves: the
// lowest frequency), so the design builder and `vicc_glyph modify` refuse it.

#include <string>

namespace vicc_glyphs {
namespace pacemod {

/// "curve N: <reason>" for the first report when every report has a `skipped` reason; empty
/// when a curve took the modification or there are no reports.
template <class Reports>
std::string nothingModifiedReason(const Reports& reports) {
  if (reports.empty()) return "";
  for (const auto& report : reports) {
    if (report.skipped.empty()) return "";
  }
  return "curve " + std::to_string(reports.front().curve) + ": " + reports.front().skipped;
}

}  // namespace pacemod
}  // namespace vicc_glyphs
