#pragma once
// Full multigrid (FMG) for the GridProblem hierarchy of one image. Every level is its own
// problem, assembled by re-rasterising the curves at that level's resolution (averaging fine
// constraints into coarse cells does not give a usable coarse problem, see rendering.md):
// - FMG: the coarsest problem is smoothed to convergence, its solution is interpolated as the
//   initial guess of the next finer problem, which gets `intermediate_cycles` iterations, and
//   so on up to the finest level, which iterates until the error estimate is at most
//   `tolerance` (or for `fine_cycles` iterations when the tolerance is 0).
// - Iteration: conjugate gradients preconditioned by one V-cycle (multigrid-preconditioned
//   CG), robust where barriers leave regions that the coarse problems couple much more weakly
//   or strongly than the fine one (a plain V-cycle iteration diverges or stalls there).
// - V-cycle: red-black Gauss-Seidel pre-smoothing and its adjoint (black-red) post-smoothing,
//   the residual restricted with the transpose of the curve-aware bilinear prolongation
//   (cell-centred grids, unscaled Laplacian), the coarse level's operator with zero correction
//   at its Dirichlet cells: a symmetric positive definite preconditioner.

#include <functional>
#include <memory>
#include <vector>

#include "vicc_glyphs/render/grid_problem.hpp"

namespace vicc_glyphs {

struct MultigridOptions {
  int pre_smoothing = 3;          ///< red-black sweeps before the coarse correction
  int post_smoothing = 3;         ///< black-red sweeps after it (equal counts: symmetric)
  int intermediate_cycles = 1;    ///< CG iterations on each level between coarsest and finest
  int coarsest_sweeps = 100;      ///< smoothing sweeps that solve the coarsest level (even)
  int coarsest_size = 16;         ///< coarsen until the larger grid side is at most this
  bool record_residuals = false;  ///< record the finest level's residuals and estimates
  /// > 0 (the default): iterate on the finest level until the error estimate, the largest
  /// magnitude of the (balanced) V-cycle's correction B r over the free pixels and channels
  /// (colour units, 0..1), is at most this, at most `max_fine_cycles` times; the history is
  /// then always recorded. 0: `fine_cycles` iterations, whatever the error.
  double tolerance = kDefaultTolerance;
  int max_fine_cycles = 50;
  int fine_cycles = 2;  ///< iterations on the finest level when tolerance is 0

  /// About half an 8-bit colour step (1/510): on the ladybug DCI (the slowest sample) the
  /// true largest error is then about 7x this, the mean error 0.003 (docs/rendering.md).
  static constexpr double kDefaultTolerance = 2e-3;
};

struct MultigridReport {
  int levels = 0;
  int fine_cycles = 0;  ///< CG iterations (one V-cycle each) done on the finest level
  /// With a tolerance: whether the error estimate reached it within max_fine_cycles.
  bool converged = false;
  /// Over the finest level's free pixels and all channels (with record_residuals or a
  /// tolerance): RMS residual (entry 0 at the FMG start, entry k after iteration k); error
  /// estimate (largest magnitude, see tolerance) of the iterate after iteration k (entry k;
  /// with a tolerance the last one is the one that met it); RMS update of iteration k+1
  /// (entry k).
  std::vector<double> residuals;
  std::vector<double> error_estimates;
  std::vector<double> updates;
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
