// Glyph bench: for each input, the time of a one-shot render (fresh renderer, as the CLI's),
// the median time of rendering it at the bench size on one thread (renderer reused, as in a
// long-running node), the multigrid's mean and largest absolute error against the direct
// sparse solve of the same discrete problem, and the CG iteration count with the default
// stopping criterion. Prints a Markdown table row per input.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <iomanip>
#include <iostream>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "bench_timing.hpp"
#include "direct_reference_solve.hpp"
#include "vicc_common/command_line.hpp"
#include "vicc_glyphs/io/load.hpp"
#include "vicc_glyphs/render/renderer.hpp"

namespace {

using namespace vicc_glyphs;

struct Measurement {
  double one_shot_ms = 0.0;  // the first render, with a fresh renderer: first-touch page faults
  double median_ms = 0.0;
  double median_cpu_ms = 0.0;
  double median_solve_ms = 0.0;
  double mae = 0.0;
  double max_error = 0.0;
  int levels = 0;
  int cycles = 0;
  bool converged = false;
  double final_estimate = 0.0;
  int curves = 0;
};

Measurement measure(const std::string& path, int size, int repeats, double tolerance) {
  const DiffusionCurveImage image = loadDiffusionCurves(path, size);
  Measurement m;
  m.curves = static_cast<int>(image.curves.size());
  DiffusionCurveRenderer renderer;
  RenderResult result;
  RenderOptions options;
  if (tolerance >= 0.0) options.multigrid.tolerance = tolerance;
  std::vector<double> totals, cpu, solves;
  for (int k = 0; k < repeats + 1; ++k) {
    const double cpu_start = bench::threadCpuMilliseconds();
    renderer.render(image, options, result);
    if (k == 0) {  // a one-shot render (as the CLI's): it also pays for first-touch page faults
      m.one_shot_ms = result.report.timings.total_ms;
      continue;
    }
    cpu.push_back(bench::threadCpuMilliseconds() - cpu_start);
    totals.push_back(result.report.timings.total_ms);
    solves.push_back(result.report.timings.solve_ms);
  }
  m.median_ms = bench::median(totals);
  m.median_cpu_ms = bench::median(cpu);
  m.median_solve_ms = bench::median(solves);
  m.levels = result.report.multigrid.levels;
  m.cycles = result.report.multigrid.fine_cycles;
  m.converged = result.report.multigrid.converged;

  // Accuracy and residual from separate runs, so they do not disturb the timing.
  const GridProblem problem =
      assembleColorProblem(image, image.width, image.height, 1.0, options.background);
  MultigridOptions recorded = options.multigrid;
  recorded.record_residuals = true;
  MultigridReport report;
  const std::vector<float> multigrid = solveMultigrid(problem, recorded, &report);
  const std::vector<float> direct = solveDirect(problem);
  m.mae = meanAbsoluteError(multigrid, direct);
  for (size_t i = 0; i < direct.size(); ++i) {
    m.max_error = std::max(m.max_error, std::abs(double(multigrid[i]) - direct[i]));
  }
  m.final_estimate = report.error_estimates.empty() ? 0.0 : report.error_estimates.back();
  return m;
}

namespace cli = vicc_common::cli;

const std::vector<cli::OptionSpec> kOptionSpecs = {
    {"size", "N", "edge length in pixels (default 512)"},
    {"repeats", "N", "timed renders per input after the first (default 21)"},
    {"tolerance", "E", "stopping tolerance instead of the renderer's default"},
};

std::string usage() {
  return cli::helpText("vicc_glyph_bench [--size N] [--repeats N] [--tolerance E] INPUT...",
                       "Render time, CG iterations and the error against a direct solve per "
                       "input (Markdown table on stdout).\nExit code 0 on success, 1 if an input "
                       "failed, 2 on a usage error.",
                       kOptionSpecs);
}

int run(const std::vector<std::string>& args) {
  const cli::ParsedArguments parsed = cli::parseArguments(args, kOptionSpecs);
  if (parsed.positional.empty()) throw cli::UsageError("no input given");
  const int size = parsed.integer("size", 512, 16, 8192);
  const int repeats = parsed.integer("repeats", 21, 1, 100000);
  const double tolerance = parsed.number("tolerance", -1.0, 0.0, 1.0);  // < 0: the default
  const std::vector<std::string>& inputs = parsed.positional;
  cv::setNumThreads(1);  // one core: no OpenCV worker threads
  Eigen::setNbThreads(1);
  std::cout << "| input | curves | size | one-shot ms | median ms | median CPU ms | solve ms | "
               "levels | CG iterations | converged | error estimate | MAE vs direct | max error vs "
               "direct |\n"
               "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  int failures = 0;
  for (const std::string& input : inputs) {
    const std::string name = input.substr(input.find_last_of('/') + 1);
    try {
      const Measurement m = measure(input, size, repeats, tolerance);
      std::cout << std::fixed << "| " << name << " | " << m.curves << " | " << size << " | "
                << std::setprecision(2) << m.one_shot_ms << " | " << m.median_ms << " | "
                << m.median_cpu_ms << " | " << m.median_solve_ms << " | " << m.levels << " | "
                << m.cycles << " | " << (m.converged ? "yes" : "no") << " | " << std::scientific
                << std::setprecision(2) << m.final_estimate << " | " << std::fixed
                << std::setprecision(5) << m.mae << " | " << m.max_error << " |\n";
    } catch (const std::exception& e) {
      std::cerr << name << ": " << e.what() << "\n";
      ++failures;
    }
  }
  return failures ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  return cli::runTool("vicc_glyph_bench", argc, argv, usage(), run);
}
