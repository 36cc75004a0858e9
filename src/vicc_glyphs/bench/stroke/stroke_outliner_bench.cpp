// vicc_glyphs_stroke_bench [--repeats N]: the two stroke outliners (Clipper's offsetting of the
// flattened path, svg_stroke.cpp; own offset curves, curve_stroke.cpp) on the accuracy cases of
// stroke_accuracy.hpp: deviation of the outline from the true stroke, vertex count and outline
// time (CPU microseconds per stroke, mean of N back-to-back runs in this process). Prints the
// Markdown table of bench/fidelity/README.md (session 18).

#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include "curve_stroke.hpp"
#include "stroke_accuracy.hpp"
#include "vicc_common/command_line.hpp"

using namespace vicc_glyphs::io_detail;
namespace cli = vicc_common::cli;

namespace {

const std::vector<cli::OptionSpec> kOptionSpecs = {
    {"repeats", "N", "outline each case N times for its time (default 20)"},
};

std::string usage() {
  return cli::helpText(
      "vicc_glyphs_stroke_bench [--repeats N]",
      "Outlines round-capped, round-joined test strokes with Clipper's offsetting and with the "
      "own offset curves;\nprints per case the largest and mean deviation of the outline's "
      "vertices from the true stroke (px),\nthe vertex count and the CPU time per outline (us). "
      "Exit code 0 on success, 1 on an error, 2 on a usage error.",
      kOptionSpecs);
}

double cpuMicroseconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return 1e6 * static_cast<double>(now.tv_sec) + 1e-3 * static_cast<double>(now.tv_nsec);
}

int run(const std::vector<std::string>& args) {
  const cli::ParsedArguments parsed = cli::parseArguments(args, kOptionSpecs);
  if (!parsed.positional.empty()) throw cli::UsageError("no positional arguments expected");
  const int repeats = static_cast<int>(parsed.number("repeats", 20, 1, 100000));
  const IntegerFrame& frame = stroke_accuracy::caseFrame();
  std::printf("| curve | width px | outliner | max dev px | mean dev px | vertices | us |\n");
  std::printf("|---|---:|---|---:|---:|---:|---:|\n");
  for (const stroke_accuracy::AccuracyCase& c : stroke_accuracy::accuracyCases()) {
    const StrokeGeometry stroke = stroke_accuracy::roundStroke(c.width);
    for (const bool own : {false, true}) {
      Paths area;
      const double start = cpuMicroseconds();
      for (int i = 0; i < repeats; ++i) {
        VertexBudget budget(1000000);
        area = (own ? curveStrokeArea : strokeArea)(c.subpaths, Affine2::Identity(), stroke, frame,
                                                    stroke_accuracy::kTolerance, budget);
      }
      const double us = (cpuMicroseconds() - start) / repeats;
      const stroke_accuracy::Deviation d =
          stroke_accuracy::deviation(area, frame, c.subpaths, 0.5 * c.width);
      std::printf("| %s | %.1f | %s | %.4f | %.4f | %zu | %.0f |\n", c.name.c_str(), c.width,
                  own ? "curves" : "clipper", d.max, d.mean, d.vertices, us);
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return cli::runTool("vicc_glyphs_stroke_bench", argc, argv, usage(), run);
}
