#include "render_command.hpp"

#include <cmath>
#include <cstdlib>
#include <iomanip>

#include "command_line.hpp"
#include "vicc_glyphs/io/load.hpp"
#include "vicc_glyphs/io/orzan_xml.hpp"
#include "vicc_glyphs/render/png_output.hpp"
#include "vicc_glyphs/render/renderer.hpp"

namespace vicc_glyphs::tools {
namespace {

constexpr int kMaxSize = 16384;

const std::vector<OptionSpec>& renderOptions() {
  static const std::vector<OptionSpec> specs{
      {"out", "OUT.png", "PNG to write (required)"},
      {"size", "N", "output width in pixels (default: the input's own width)"},
      {"dci", "OUT.xml", "also write the loaded (and scaled) DCI as Orzan XML"},
      {"tolerance", "E",
       "iterate until the estimated largest colour error (0..1) is at most E (default "
       "0.002, at most 50 iterations)"},
      {"cycles", "N",
       "instead: N iterations (V-cycles) on the finest grid (fewer once the correction is "
       "below float resolution)"},
      {"color", "RRGGBB", "SVG: the colour of currentColor (default 000000, black)"},
      {"lenient", "", "SVG: unsupported features become warnings and are left out"},
      {"stroke-outliner", "clipper|curves",
       "SVG: strokes outlined by Clipper's offsetting of the flattened path (default) or by "
       "offset curves of the Beziers"},
      {"report", "", "print timings, multigrid levels and residuals"},
      {"help", "", "show this help"},
  };
  return specs;
}

void printUsage(std::ostream& out) {
  out << "usage: vicc_glyph render INPUT.(svg|xml|png) --out OUT.png [--size N] [--dci OUT.xml]\n"
         "                        [--tolerance E | --cycles N]\n"
         "                        [--color RRGGBB] [--lenient] [--stroke-outliner clipper|curves]\n"
         "                        [--report]\n\n"
         "Renders a diffusion curve image (Orzan XML), an SVG icon or a PNG (traced) to PNG.\n\n"
      << formatOptions(renderOptions());
}

void printReport(const RenderResult& result, std::ostream& out) {
  const RenderReport& report = result.report;
  const RenderTimings& t = report.timings;
  out << std::fixed << std::setprecision(2) << "size: " << result.image.cols << "x"
      << result.image.rows << "\n"
      << "time ms: total " << t.total_ms << ", assemble " << t.assemble_ms << ", solve "
      << t.solve_ms << ", antialias " << t.antialias_ms << ", blur " << t.blur_ms << "\n";
  if (report.multigrid.constant_regions) {
    out << "multigrid: not needed, every free region has one Dirichlet value (its exact "
           "solution)\n"
        << std::defaultfloat;
    return;
  }
  out << "multigrid: " << report.multigrid.levels << " levels, "
      << report.multigrid.next_to_finest_cycles << " FMG V-cycles next to the finest grid, "
      << report.multigrid.fine_cycles << " CG iterations (V-cycles) on the finest grid"
      << (report.multigrid.converged ? " (error tolerance reached)" : "")
      << (report.multigrid.stopped_at_float_resolution
              ? " (stopped before the count: the correction fell below float resolution)"
              : "")
      << "\n"
      << std::scientific << std::setprecision(3);
  const MultigridReport& m = report.multigrid;
  for (size_t k = 0; k < m.residuals.size(); ++k) {
    out << "  " << (k == 0 ? "FMG start  " : "iteration " + std::to_string(k)) << ": rms residual "
        << m.residuals[k];
    if (k < m.error_estimates.size()) out << ", estimated max error " << m.error_estimates[k];
    out << "\n";
  }
  out << std::defaultfloat;
}

// "RRGGBB" (optionally with a leading '#') as a colour in [0, 1].
Color parseHexColor(const std::string& text) {
  const std::string hex = !text.empty() && text[0] == '#' ? text.substr(1) : text;
  if (hex.size() != 6 || hex.find_first_not_of("0123456789abcdefABCDEF") != std::string::npos) {
    throw UsageError("--color needs RRGGBB (6 hex digits), got '" + text + "'");
  }
  Color color;
  for (int i = 0; i < 3; ++i) color[i] = std::stoi(hex.substr(2 * i, 2), nullptr, 16) / 255.0;
  return color;
}

StrokeOutliner parseStrokeOutliner(const std::string& text) {
  if (text == "clipper") return StrokeOutliner::kClipper;
  if (text == "curves") return StrokeOutliner::kCurves;
  throw UsageError("--stroke-outliner needs clipper or curves, got '" + text + "'");
}

}  // namespace

int runRenderCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  RenderOptions options;
  std::string input, output, dci;
  int size = 0;
  bool report = false;
  SvgImportOptions svg;
  svg.warn = [&err](const std::string& warning) {
    err << "vicc_glyph render: warning: " << warning << "\n";
  };
  const auto read = [&](const ParsedArguments& parsed) {
    if (parsed.positional.size() != 1) {
      throw UsageError(parsed.positional.empty() ? "missing INPUT file"
                                                 : "expected one INPUT file, got " +
                                                       std::to_string(parsed.positional.size()));
    }
    input = parsed.positional.front();
    output = parsed.value("out");
    if (output.empty()) throw UsageError("missing --out OUT.png");
    if (parsed.has("size")) size = parseInteger("size", parsed.value("size"), 1, kMaxSize);
    if (parsed.has("cycles") && parsed.has("tolerance")) {
      throw UsageError("--cycles and --tolerance exclude each other");
    }
    if (parsed.has("cycles")) {
      options.multigrid.fine_cycles = parseInteger("cycles", parsed.value("cycles"), 0, 100);
      options.multigrid.tolerance = 0.0;
    }
    if (parsed.has("tolerance")) {
      const std::string text = parsed.value("tolerance");
      char* end = nullptr;
      const double tolerance = std::strtod(text.c_str(), &end);
      if (text.empty() || *end != '\0' || !(tolerance > 0.0) || !std::isfinite(tolerance)) {
        throw UsageError("--tolerance needs a positive number, got '" + text + "'");
      }
      options.multigrid.tolerance = tolerance;
    }
    if (parsed.has("color")) svg.current_color = parseHexColor(parsed.value("color"));
    svg.lenient = parsed.has("lenient");
    if (parsed.has("stroke-outliner")) {
      svg.stroke_outliner = parseStrokeOutliner(parsed.value("stroke-outliner"));
    }
    dci = parsed.value("dci");
    report = parsed.has("report");
    requireDistinctFiles({{"INPUT", input}, {"--out", output}, {"--dci", dci}});
  };
  const std::optional<int> done =
      readCommandLine("render", args, renderOptions(), printUsage, out, err, read);
  if (done) return *done;
  options.multigrid.record_residuals = report;

  try {
    const DiffusionCurveImage image = loadDiffusionCurves(input, size, svg);
    RenderResult result;
    DiffusionCurveRenderer().render(image, options, result);
    requireSomethingDrawn(result.report, input);
    if (!dci.empty()) writeOrzanXml(image, dci);
    writePng(result.image, output);
    const MultigridOptions& solver = options.multigrid;
    if (solver.tolerance > 0.0 && !result.report.multigrid.converged) {
      err << "vicc_glyph render: warning: the diffusion did not reach the error tolerance "
          << solver.tolerance << " in " << solver.max_fine_cycles << " iterations\n";
    }
    if (report) printReport(result, out);
  } catch (const std::exception& e) {
    err << "vicc_glyph render: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace vicc_glyphs::tools
