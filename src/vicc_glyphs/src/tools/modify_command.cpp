#include "modify_command.hpp"

#include <fstream>
#include <optional>

#include "modify_report.hpp"
#include "modify_request.hpp"
#include "vicc_glyphs/io/load.hpp"
#include "vicc_glyphs/io/orzan_xml.hpp"
#include "vicc_glyphs/pacemod/image_frame.hpp"
#include "vicc_glyphs/pacemod/skipped_curves.hpp"
#include "vicc_glyphs/render/png_output.hpp"
#include "vicc_glyphs/render/renderer.hpp"

namespace vicc_glyphs::tools {
namespace {

void printUsage(std::ostream& out) {
  out << "usage: vicc_glyph modify INPUT.(svg|xml|png) --out OUT.png [--dci OUT.xml] [--size PX]\n"
         "         [--size-mm MM] [--waveform sine|triangle|sawtooth|rectangle]\n"
         "         [--frequency WAVES_PER_10MM] [--amplitude MM] [--curves all|outer|I,J,...]\n"
         "         [--dashes N --dash-color RRGGBB] [--inflate MM] [--report OUT.json]\n\n"
         "PACEMOD contour modifications (thesis 6.2.3-6.2.4): inflate/shrink, then periodic\n"
         "waves, then colour dashes, on the selected curves; the glyph is --size-mm wide.\n\n"
      << formatOptions(modifyOptions());
}

// Applies the modifications in the order inflate, waves, dashes (dashes follow the final
// geometry). Throws std::invalid_argument for parameters that do not fit the icon.
ModifyOutcome modify(const ModifyRequest& request, DiffusionCurveImage& image) {
  ModifyOutcome outcome;
  outcome.selected = pacemod::selectCurves(image, request.curves);
  if (request.inflate_mm) {
    outcome.inflated =
        pacemod::inflateCurves(image, outcome.selected, *request.inflate_mm, request.size_mm);
  }
  if (request.waves) {
    outcome.waves = pacemod::applyWaves(image, outcome.selected, *request.waves, request.size_mm);
  }
  if (request.dashes) {
    outcome.dashes =
        pacemod::applyDashes(image, outcome.selected, *request.dashes, request.size_mm);
  }
  outcome.curve_count = static_cast<int>(image.curves.size());
  return outcome;
}

// A modification that carries a curve out of the frame (an inflation or amplitude near the
// limit of a quarter of the glyph) would be clipped: part of the encoding cut off.
void requireInsideFrame(const DiffusionCurveImage& before, const DiffusionCurveImage& after,
                        const std::vector<int>& selected) {
  const std::optional<int> out = pacemod::curveCarriedOutOfFrame(before, after, selected);
  if (!out) return;
  throw std::runtime_error("the modification carries curve " + std::to_string(*out) +
                           " out of the " + std::to_string(after.width) + " x " +
                           std::to_string(after.height) +
                           " px image, where it would be clipped (a smaller --inflate or "
                           "--amplitude, or a larger --size-mm)");
}

// A curve a modification left as it was must not pass unnoticed: the picture would look like a
// modified glyph that encodes nothing (or the lowest level). No curve at all: an error, no file.
template <class Reports>
void requireTakenAndWarnSkipped(const Reports& reports, const char* what, std::ostream& err) {
  const std::string nothing = pacemod::nothingModifiedReason(reports);
  if (!nothing.empty()) {
    throw std::runtime_error(std::string("the ") + what +
                             " cannot be drawn on any selected curve (" + nothing +
                             "): the glyph would look unmodified");
  }
  for (const auto& report : reports) {
    if (report.skipped.empty()) continue;
    err << "vicc_glyph modify: warning: curve " << report.curve << ": " << what
        << " not applied: " << report.skipped << "\n";
  }
}

void writeReport(const ModifyRequest& request, const ModifyOutcome& outcome) {
  std::ofstream file(request.report);
  file << modifyReportJson(request, outcome).dump(2) << "\n";
  if (!file) throw std::runtime_error("cannot write report " + request.report);
}

}  // namespace

int runModifyCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  ModifyRequest request;
  try {
    request = parseModifyRequest(args);
  } catch (const UsageError& e) {
    err << "vicc_glyph modify: " << e.what() << "\n\n";
    printUsage(err);
    return 2;
  }
  if (request.help) {
    printUsage(out);
    return 0;
  }
  try {
    DiffusionCurveImage image = loadDiffusionCurves(request.input, request.size);
    const DiffusionCurveImage original = image;
    ModifyOutcome outcome = modify(request, image);
    requireInsideFrame(original, image, outcome.selected);
    requireTakenAndWarnSkipped(outcome.inflated, "inflation", err);
    requireTakenAndWarnSkipped(outcome.waves, "waves", err);
    requireTakenAndWarnSkipped(outcome.dashes, "dashes", err);
    const std::string problem = validate(image);
    if (!problem.empty()) throw std::runtime_error("modified image is invalid: " + problem);
    RenderResult result;
    DiffusionCurveRenderer().render(image, RenderOptions{}, result);
    requireSomethingDrawn(result.report, request.input);
    if (!request.dci.empty()) writeOrzanXml(image, request.dci);
    outcome.render_ms = result.report.timings.total_ms;
    writePng(result.image, request.output);
    if (!request.report.empty()) writeReport(request, outcome);
  } catch (const std::exception& e) {
    err << "vicc_glyph modify: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace vicc_glyphs::tools
