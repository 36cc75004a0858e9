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

#include "direct_reference_solve.hpp"
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

// CPU time of this thread: unlike wall time it does not count other processes sharing the
// core (the bench machine is shared).
double threadCpuMilliseconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return now.tv_sec * 1e3 + now.tv_nsec * 1e-6;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

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
    const double cpu_start = threadCpuMilliseconds();
    renderer.render(image, options, result);
    if (k == 0) {  // a one-shot render (as the CLI's): it also pays for first-touch page faults
      m.one_shot_ms = result.report.timings.total_ms;
      continue;
    }
    cpu.push_back(threadCpuMilliseconds() - cpu_start);
    totals.push_back(result.report.timings.total_ms);
    solves.push_back(result.report.timings.solve_ms);
  }
  m.median_ms = median(totals);
  m.median_cpu_ms = median(cpu);
  m.median_solve_ms = median(solves);
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

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: vicc_glyph_bench [--size N] [--repeats N] [--tolerance E] INPUT...\n";
    return 2;
  }
  cv::setNumThreads(1);  // one core: no OpenCV worker threads
  Eigen::setNbThreads(1);
  int size = 512, repeats = 21;
  double tolerance = -1.0;  // < 0: the renderer's default stopping criterion
  std::vector<std::string> inputs;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if ((arg == "--size" || arg == "--repeats") && i + 1 < argc) {
      (arg == "--size" ? size : repeats) = std::max(1, std::atoi(argv[++i]));
    } else if (arg == "--tolerance" && i + 1 < argc) {
      tolerance = std::max(0.0, std::atof(argv[++i]));
    } else {
      inputs.push_back(arg);
    }
  }
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
