// Convergence history of the diffusion solve: for each input, per CG iteration on the finest
// grid, the rms residual, the error estimate the stopping criterion uses (largest magnitude of
// the V-cycle's correction over the smallest eigenvalue CG has met, see rendering.md) and the
// true error against Eigen's direct solve of the same discrete problem (mean absolute and
// maximum). Shows whether the default tolerance stops where the error is small enough. Prints a
// Markdown table per input; its heading gives the default solve's iterations, last estimate
// and the true errors of its result (which also has the last estimate's correction added).

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include "direct_reference_solve.hpp"
#include "vicc_common/command_line.hpp"
#include "vicc_glyphs/io/load.hpp"
#include "vicc_glyphs/render/renderer.hpp"

namespace {

using namespace vicc_glyphs;

void printHistory(const std::string& path, int size, int iterations) {
  const DiffusionCurveImage image = loadDiffusionCurves(path, size);
  // Where the multigrid itself stops: a flat-colour icon would otherwise take its exact
  // constants without iterating (MultigridOptions::constant_regions).
  MultigridOptions defaults;
  defaults.constant_regions = false;
  const GridProblem problem =
      assembleColorProblem(image, image.width, image.height, 1.0, Color::Zero());
  const std::vector<float> direct = solveDirect(problem);
  MultigridSolver solver;
  MultigridReport full;
  {
    MultigridOptions options;
    options.tolerance = 0.0;
    options.fine_cycles = iterations;
    options.record_residuals = true;
    std::vector<float> values;
    solver.solve(problem, options, values, &full);
  }
  MultigridReport stopped;
  std::vector<float> values;
  solver.solve(problem, defaults, values, &stopped);
  std::cout << "\n### " << path.substr(path.find_last_of('/') + 1) << " at " << size
            << " px (default tolerance " << defaults.tolerance << " stops after "
            << stopped.fine_cycles << " iterations at estimate " << std::scientific
            << std::setprecision(2) << stopped.error_estimates.back() << ": MAE "
            << meanAbsoluteError(values, direct) << ", max error "
            << maxAbsoluteError(values, direct) << ")\n\n"
            << "| iteration | rms residual | error estimate | rms update | MAE vs direct | max "
               "error |\n|---:|---:|---:|---:|---:|---:|\n";
  // The fixed-count run stops early once the V-cycle's correction is below float resolution
  // (see rendering.md): it has recorded fewer iterations than asked for, and so has the table.
  const int recorded = std::min(iterations, static_cast<int>(full.residuals.size()) - 1);
  for (int k = 0; k <= recorded; ++k) {
    MultigridOptions options;
    options.tolerance = 0.0;
    options.fine_cycles = k;
    solver.solve(problem, options, values, nullptr);
    std::cout << "| " << k << " | " << std::scientific << std::setprecision(2) << full.residuals[k]
              << " | "
              << (k < static_cast<int>(full.error_estimates.size()) ? full.error_estimates[k] : NAN)
              << " | "
              << (k > 0 && k <= static_cast<int>(full.updates.size()) ? full.updates[k - 1] : NAN)
              << " | " << std::fixed << std::setprecision(5) << meanAbsoluteError(values, direct)
              << " | " << maxAbsoluteError(values, direct) << " |\n";
  }
  if (recorded < iterations) {
    std::cout << "\n(asked for " << iterations << " iterations; the solver stopped after "
              << recorded << ": "
              << (full.stopped_at_float_resolution ? "its correction was below float resolution"
                                                   : "it recorded no more")
              << ")\n";
  }
}

namespace cli = vicc_common::cli;

const std::vector<cli::OptionSpec> kOptionSpecs = {
    {"size", "N", "edge length in pixels (default 512)"},
    {"iterations", "N", "fixed iterations to record (default 20)"},
};

std::string usage() {
  return cli::helpText("vicc_glyph_convergence [--size N] [--iterations N] INPUT...",
                       "Per-iteration residual, error estimate and true error of the solver for "
                       "each input.\nExit code 0 on success, 1 if an input failed, 2 on a usage "
                       "error.",
                       kOptionSpecs);
}

int run(const std::vector<std::string>& args) {
  const cli::ParsedArguments parsed = cli::parseArguments(args, kOptionSpecs);
  if (parsed.positional.empty()) throw cli::UsageError("no input given");
  const int size = parsed.integer("size", 512, 16, 8192);
  const int iterations = parsed.integer("iterations", 20, 1, 1000);
  Eigen::setNbThreads(1);
  int failures = 0;
  for (const std::string& input : parsed.positional) {
    try {
      printHistory(input, size, iterations);
    } catch (const std::exception& e) {
      std::cerr << input << ": " << e.what() << "\n";
      ++failures;
    }
  }
  return failures ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  return cli::runTool("vicc_glyph_convergence", argc, argv, usage(), run);
}
