#pragma once
// Full multigrid (FMG) for the GridProblem hierarchy of one image. Every level is its own
// problem, assembled by re-rasterising the curves at that level's resolution (averaging fine
// constraints into coarse cells does not give a usable coarse problem, see rendering.md):
// - FMG: the coarsest problem is smoothed to convergence, its solution is interpolated as the
//   initial guess of the next finer problem, which gets `intermediate_cycles` V-cycles, and so
//   on up to the finest level, which gets `fine_cycles` V-cycles.
// - V-cycle: red-black Gauss-Seidel smoothing, residual restricted by summing 2x2 children
//   (cell-centred grids, unscaled Laplacian), the coarse level's operator with zero correction
//   at its Dirichlet cells, bilinear prolongation of the correction.

#include <functional>
#include <memory>
#include <vector>

#include "vicc_glyphs/render/grid_problem.hpp"

namespace vicc_glyphs {

struct MultigridOptions {
  int pre_smoothing = 2;          ///< red-black sweeps before the coarse correction
  int post_smoothing = 2;         ///< red-black sweeps after it
  int intermediate_cycles = 1;    ///< V-cycles on each level between coarsest and finest (FMG)
  int fine_cycles = 2;            ///< V-cycles on the finest level
  int coarsest_sweeps = 100;      ///< smoothing sweeps that solve the coarsest level
  int coarsest_size = 4;          ///< coarsen until the larger grid side is at most this
  bool record_residuals = false;  ///< compute the finest level's residual after each cycle
  /// > 0: instead of `fine_cycles`, V-cycle the finest level until its rms residual is at most
  /// this (or `max_fine_cycles` are done); the residuals are then always recorded.
  double residual_tolerance = 0.0;
  int max_fine_cycles = 50;
};

struct MultigridReport {
  int levels = 0;
  int fine_cycles = 0;  ///< V-cycles done on the finest level
  /// With residual_tolerance: whether the residual reached it within max_fine_cycles.
  bool converged = false;
  /// RMS residual over the finest level's free pixels and all channels: entry 0 after the FMG
  /// interpolation, entry k after fine V-cycle k (only with record_residuals).
  std::vector<double> residuals;
};

/// Grid sizes of the hierarchy, finest first: each level halves (rounding up) the previous one
/// until the larger side is at most `coarsest_size` (a side of 1 stays 1).
std::vector<std::pair<int, int>> levelSizes(int width, int height, int coarsest_size);

/// Assembles the hierarchy into `levels` (reusing its storage): `assemble(width, height,
/// scale, level)` fills every level, with scale = 2^-level (grid pixels per image pixel), so
/// each level re-rasterises the curves.
void assembleLevels(
    int width, int height, int coarsest_size,
    const std::function<void(int width, int height, double scale, GridProblem& level)>& assemble,
    std::vector<GridProblem>& levels);

/// Solves hierarchies, keeping its working memory between solves (fresh memory costs page
/// faults that can take longer than the solve itself).
class MultigridSolver {
 public:
  MultigridSolver();
  ~MultigridSolver();
  MultigridSolver(const MultigridSolver&) = delete;
  MultigridSolver& operator=(const MultigridSolver&) = delete;

  /// Solves levels[0] (finest first; all levels with the same channel count, 1 or 3, each
  /// half the size of the one before, rounding up). Writes width*height*channels values,
  /// pixel-major like GridProblem::values, to `values`. Throws std::invalid_argument on bad
  /// input.
  void solve(const std::vector<GridProblem>& levels, const MultigridOptions& options,
             std::vector<float>& values, MultigridReport* report);
  /// As above, writing to `values` (room for width*height*channels floats of levels[0]), e.g.
  /// straight into an output cv::Mat.
  void solve(const std::vector<GridProblem>& levels, const MultigridOptions& options, float* values,
             MultigridReport* report);

 private:
  struct Workspaces;
  std::unique_ptr<Workspaces> workspaces_;
};

/// One-off solve with a temporary MultigridSolver.
std::vector<float> solveMultigrid(const std::vector<GridProblem>& levels,
                                  const MultigridOptions& options, MultigridReport* report);

}  // namespace vicc_glyphs
