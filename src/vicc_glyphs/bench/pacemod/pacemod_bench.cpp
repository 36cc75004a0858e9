// PACEMOD wave benchmark: every icon of data/icons x waveforms x frequencies x amplitudes.
// Each glyph is imported at 512 px (50 mm wide), waved with applyWaves on all curves and
// rendered; then, on the result, the waves along each modified contour are counted and their
// amplitudes measured from the distance to the original contour (wave_measurement.hpp), and
// all polygons are checked for crossings. Prints Markdown tables (see README.md here).
// Usage (--help): vicc_glyphs_pacemod_bench [ICON_DIR] [--quick] [--verbose] [--nearest-point M]
//        [--waveform sine|triangle|sawtooth|rectangle] [--no-render]
//        [--icon NAME.svg] [--frequency WAVES_PER_10MM] [--amplitude MM] [--overlays DIR]
//        [--times FILE.tsv] [--repeats N] [--default-heap]

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench_timing.hpp"
#include "contour_overlay.hpp"
#include "vicc_common/command_line.hpp"
#include "vicc_glyphs/io/load.hpp"
#include "vicc_glyphs/pacemod/curve_selection.hpp"
#include "vicc_glyphs/pacemod/periodic_waves.hpp"
#include "vicc_glyphs/pacemod/wave_layout.hpp"
#include "vicc_glyphs/render/renderer.hpp"
#include "wave_check.hpp"

namespace fs = std::filesystem;
using namespace vicc_glyphs;
using namespace vicc_glyphs::pacemod;

namespace {

constexpr int kSize = 512;
constexpr double kSizeMm = 50.0;

bool verbose = false;
bool render_glyphs = true;  // --no-render: checks only (faster searches for failures)
WaveOptions options;
// --overlays: an SVG picture of every glyph that fails a check or has a new sharp turn.
std::string overlay_dir;
std::FILE* times_file = nullptr;  // --times: one line per glyph
int repeats = 1;  // --repeats: each glyph made N times, the fastest run's times kept

struct Totals {
  int glyphs = 0;
  measure::GlyphCheck check;
  std::vector<double> total_ms, modify_ms, render_ms;
};

// CPU ms of one glyph's import, modification and rendering.
struct GlyphTimes {
  double import_ms = 0.0, modify_ms = 0.0, render_ms = 0.0;
  double total() const { return import_ms + modify_ms + render_ms; }
};

void runGlyph(const fs::path& icon, const WaveSpec& spec, DiffusionCurveRenderer& renderer,
              RenderResult& result, Totals& totals) {
  DiffusionCurveImage original, image;
  std::vector<CurveWaveReport> reports;
  const GlyphTimes fastest = bench::fastestRun(repeats, [&] {
    const double start = bench::threadCpuMilliseconds();
    image = loadDiffusionCurves(icon.string(), kSize);
    const double modify_start = bench::threadCpuMilliseconds();
    original = image;  // outside the times: a copy for the checks
    const double copied = bench::threadCpuMilliseconds();
    reports = applyWaves(image, selectCurves(image, {}), spec, kSizeMm, options);
    const double render_start = bench::threadCpuMilliseconds();
    if (render_glyphs) renderer.render(image, RenderOptions{}, result);
    const double end = bench::threadCpuMilliseconds();
    return GlyphTimes{modify_start - start, render_start - copied, end - render_start};
  });
  totals.modify_ms.push_back(fastest.modify_ms);
  totals.render_ms.push_back(fastest.render_ms);
  totals.total_ms.push_back(fastest.total());
  ++totals.glyphs;
  if (times_file) {
    std::fprintf(times_file, "%s\t%s\t%g\t%g\t%.2f\t%.2f\t%.2f\t%.2f\t%d\t%d\n",
                 icon.filename().c_str(), waveformName(spec.waveform).c_str(),
                 spec.waves_per_mm * 10, spec.amplitude_mm, fastest.import_ms, fastest.modify_ms,
                 fastest.render_ms, fastest.total(),
                 render_glyphs ? result.report.multigrid.fine_cycles : -1,
                 render_glyphs ? int{result.report.multigrid.constant_regions} : -1);
  }
  const measure::GlyphCheck check =
      measure::checkGlyph(original, image, reports, spec, kSize / kSizeMm);
  if (verbose && (check.new_crossings > 0 || check.new_subpixel_loops > 0 ||
                  check.new_sharp_turns > 0 || !check.failures.empty())) {
    std::fprintf(stderr,
                 "%s %s f=%g a=%g: crossings %d, sub-pixel loops %d, sharp turns %d, full lobes "
                 "%d/%d, reduced lobes %d/%d, count %d/%d + %d/%d reduced\n",
                 icon.filename().c_str(), waveformName(spec.waveform).c_str(),
                 spec.waves_per_mm * 10, spec.amplitude_mm, check.new_crossings,
                 check.new_subpixel_loops, check.new_sharp_turns, check.full_lobes_ok,
                 check.full_lobes, check.reduced_lobes_ok, check.reduced_lobes,
                 check.unreduced_count_ok, check.unreduced_contours, check.reduced_count_ok,
                 check.reduced_decidable);
    for (const Point2& turn : check.sharp_turn_points) {
      std::fprintf(stderr, "    sharp turn at (%.1f, %.1f)\n", turn.x(), turn.y());
    }
  }
  if (verbose && !check.failures.empty()) {
    for (const CurveWaveReport& r : reports) {
      int crossing = 0;
      for (const PeakReduction& p : r.reductions) crossing += p.reason == "crossing";
      if (!r.reductions.empty()) {
        std::fprintf(stderr, "    curve %d: %zu of %d knot points reduced (%d by crossings)\n",
                     r.curve, r.reductions.size(), r.knot_points, crossing);
      }
    }
    for (const std::string& failure : check.failures)
      std::fprintf(stderr, "    %s\n", failure.c_str());
  }
  if (!overlay_dir.empty() && (!check.failures.empty() || check.new_sharp_turns > 0)) {
    std::vector<std::string> notes = check.failures;
    std::vector<Point2> marks = check.failure_points;
    for (const Point2& turn : check.sharp_turn_points) {
      char note[80];
      std::snprintf(note, sizeof note, "new sharp turn at (%.1f, %.1f)", turn.x(), turn.y());
      notes.push_back(note);
      marks.push_back(turn);
    }
    char name[160];
    std::snprintf(name, sizeof name, "%s/%s_%s_%g_%g.svg", overlay_dir.c_str(), icon.stem().c_str(),
                  waveformName(spec.waveform).c_str(), spec.waves_per_mm * 10, spec.amplitude_mm);
    measure::writeContourOverlay(name, original, image, reports, spec, kSize / kSizeMm, notes,
                                 marks);
  }
  measure::add(totals.check, check);
}

const char* kColumns =
    "| glyphs | contours | count ok, unreduced | count ok, reduced (decidable) | undecidable "
    "| full lobes within 10 % | median err % | worst err % | reduced lobes within 10 % of applied "
    "| worst err % | reduced knot points (by the polygon check) | new crossings "
    "| new sub-pixel loops | new sharp turns | modify ms | render ms | total ms median "
    "| total ms p95 | total ms max |\n"
    "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";

void printHeader(const char* first) {
  std::printf("| %s ", first);
  std::fputs(kColumns, stdout);
}

void printRow(const std::string& label, const Totals& t) {
  const measure::GlyphCheck& c = t.check;
  std::printf(
      "| %s | %d | %d | %d/%d | %d/%d | %d | %d/%d | %.1f | %.1f | %d/%d | %.1f | %d (%d) | %d | "
      "%d | %d | %.1f | %.1f | %.1f | %.1f | %.1f |\n",
      label.c_str(), t.glyphs, c.contours, c.unreduced_count_ok, c.unreduced_contours,
      c.reduced_count_ok, c.reduced_decidable, c.reduced_undecidable, c.full_lobes_ok, c.full_lobes,
      100.0 * c.median_full_error(), 100.0 * c.worst_full_error, c.reduced_lobes_ok,
      c.reduced_lobes, 100.0 * c.worst_reduced_error, c.reduced_peaks, c.crossing_peaks,
      c.new_crossings, c.new_subpixel_loops, c.new_sharp_turns, bench::median(t.modify_ms),
      bench::median(t.render_ms), bench::median(t.total_ms), bench::percentile95(t.total_ms),
      bench::maximum(t.total_ms));
}

namespace cli = vicc_common::cli;

const std::vector<cli::OptionSpec> kOptionSpecs = {
    {"quick", "", "one frequency (4 waves/10 mm) and one amplitude (0.5 mm)"},
    {"verbose", "", "list every glyph and lobe that fails a check, and new sharp turns"},
    {"no-render", "", "checks only, no rendering (faster searches for failures)"},
    {"nearest-point", "M",
     "the skeleton guard's nearest curve points: exact-segments (default), maurer or "
     "opencv-labels (feature transforms)"},
    {"waveform", "W", "only this waveform: sine, triangle, sawtooth or rectangle"},
    {"icon", "NAME.svg", "only this icon"},
    {"frequency", "F", "only this frequency, waves per 10 mm"},
    {"amplitude", "A", "only this amplitude, mm"},
    {"overlays", "DIR", "an SVG picture of every glyph that fails a check or has a new sharp turn"},
    {"times", "FILE.tsv", "CPU ms per glyph (import, modify, render, total) and CG iterations"},
    {"repeats", "N", "make each glyph N times; its times are the fastest run's (default 1)"},
    {"default-heap", "", "glibc's default malloc settings instead of the glyph server's"},
};

std::string usage() {
  return cli::helpText(
      "vicc_glyphs_pacemod_bench [ICON_DIR] [options]",
      "Waves every icon of ICON_DIR (default: the vendored MDI icons) for the grid of waveforms, "
      "frequencies and amplitudes;\ncounts the waves, measures their amplitudes and the new "
      "crossings (Markdown tables on stdout).\nExit code 0 on success, 1 on an error, 2 on a "
      "usage error.",
      kOptionSpecs);
}

int run(const std::vector<std::string>& args) {
  const cli::ParsedArguments parsed = cli::parseArguments(args, kOptionSpecs);
  if (parsed.positional.size() > 1) throw cli::UsageError("more than one ICON_DIR given");
  const fs::path dir = parsed.positional.empty() ? fs::path(VICC_GLYPHS_DATA_DIR "/icons")
                                                 : fs::path(parsed.positional[0]);
  if (!fs::is_directory(dir)) throw cli::UsageError("no directory " + dir.string());
  const bool quick = parsed.flag("quick");
  verbose = parsed.flag("verbose");
  render_glyphs = !parsed.flag("no-render");
  const std::string nearest_point = parsed.value("nearest-point");
  if (nearest_point == "maurer") {
    options.nearest_point_method = NearestPointMethod::Maurer;
  } else if (nearest_point == "opencv-labels") {
    options.nearest_point_method = NearestPointMethod::OpenCvLabels;
  } else if (!nearest_point.empty() && nearest_point != "exact-segments") {
    throw cli::UsageError("--nearest-point must be exact-segments, maurer or opencv-labels, not " +
                          nearest_point);
  }
  const std::string only_waveform = parsed.value("waveform");
  if (!only_waveform.empty() && only_waveform != "sine" && only_waveform != "triangle" &&
      only_waveform != "sawtooth" && only_waveform != "rectangle") {
    throw cli::UsageError("unknown --waveform '" + only_waveform + "'");
  }
  const std::string only_icon = parsed.value("icon");
  const double only_frequency = parsed.number("frequency", 0.0, 0.01, 100.0);
  const double only_amplitude = parsed.number("amplitude", -1.0, 0.0, 10.0);
  overlay_dir = parsed.value("overlays");
  repeats = parsed.integer("repeats", 1, 1, 100);
  const std::string times_path = parsed.value("times");
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> times(nullptr, &std::fclose);
  if (!times_path.empty()) {
    times.reset(std::fopen(times_path.c_str(), "w"));
    if (!times) throw std::runtime_error("cannot write " + times_path);
    std::fprintf(times.get(),
                 "icon\twaveform\twaves_per_10mm\tamplitude_mm\timport_ms\tmodify_ms\t"
                 "render_ms\ttotal_ms\tcg_iterations\tconstant_regions\n");
    times_file = times.get();
  }
  std::vector<fs::path> icons;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() == ".svg" &&
        (only_icon.empty() || entry.path().filename() == only_icon)) {
      icons.push_back(entry.path());
    }
  }
  std::sort(icons.begin(), icons.end());
  std::vector<double> frequencies =
      quick ? std::vector<double>{4} : std::vector<double>{2, 4, 8, 12};
  std::vector<double> amplitudes =
      quick ? std::vector<double>{0.5} : std::vector<double>{0.1, 0.4, 0.8, 1.2};
  if (only_frequency > 0.0) frequencies = {only_frequency};
  if (only_amplitude >= 0.0) amplitudes = {only_amplitude};
  const std::string heap = bench::heapAsInTheServer(parsed.flag("default-heap"));
  DiffusionCurveRenderer renderer;
  RenderResult result;
  std::map<std::string, Totals> by_waveform;
  std::printf(
      "%zu icons, %d px = %.0f mm, heap: %s, nearest curve points: %s, times of the fastest of "
      "%d run(s) per glyph, load average at the start %s\n\n",
      icons.size(), kSize, kSizeMm, heap.c_str(),
      nearest_point.empty() ? "exact-segments" : nearest_point.c_str(), repeats,
      bench::loadAverage().c_str());
  printHeader("waveform, waves/10 mm, amplitude mm");
  for (Waveform waveform :
       {Waveform::Sine, Waveform::Triangle, Waveform::Sawtooth, Waveform::Rectangle}) {
    if (!only_waveform.empty() && waveformName(waveform) != only_waveform) continue;
    for (double f : frequencies) {
      for (double a : amplitudes) {
        const WaveSpec spec{waveform, f / 10.0, a};
        Totals totals;
        for (const fs::path& icon : icons) runGlyph(icon, spec, renderer, result, totals);
        char label[96];
        std::snprintf(label, sizeof label, "%s, %g, %g", waveformName(waveform).c_str(), f, a);
        printRow(label, totals);
        Totals& all = by_waveform[waveformName(waveform)];
        all.glyphs += totals.glyphs;
        measure::add(all.check, totals.check);
        for (double v : totals.total_ms) all.total_ms.push_back(v);
        for (double v : totals.modify_ms) all.modify_ms.push_back(v);
        for (double v : totals.render_ms) all.render_ms.push_back(v);
      }
    }
  }
  std::printf("\n");
  printHeader("waveform (all frequencies and amplitudes)");
  for (const auto& [name, totals] : by_waveform) printRow(name, totals);
  std::printf("\nload average at the end %s\n", bench::loadAverage().c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return cli::runTool("vicc_glyphs_pacemod_bench", argc, argv, usage(), run);
}
