#pragma once
// Full multigrid (FMG) for the GridProblem of one image, with coarse operators built from the
// fine one (Galerkin, see docs/rendering.md):
// - Hierarchy: coarse point (i, j) is fine point (2i, 2j); the prolongation P is
//   operator-dependent (black box multigrid: it interpolates only along the links, and towards
//   a Dirichlet pixel it interpolates 0), the restriction is P^T and every coarse operator is
//   R A P, a 9-point stencil. So every level couples regions, gaps between barriers included,
//   exactly as strongly as the fine grid does; coarse problems are not rasterised again.
// - FMG: the Dirichlet data's right-hand side is restricted to every level, the coarsest level
//   (at most `coarsest_size` points a side) is solved directly (banded Cholesky), its solution
//   interpolated as the start of the next finer level, which gets `intermediate_cycles`
//   V-cycles, and so on; the finest level iterates until the error estimate is at most
//   `tolerance` (or for `fine_cycles` iterations when the tolerance is 0).
// - Finest level: conjugate gradients preconditioned by one V-cycle; when the first iteration
//   is slow, deflated by the constants of pieces split at one- or two-pixel necks (A-DEF2).
// - V-cycle: red-black Gauss-Seidel on the finest level (black-red after the coarse
//   correction), lexicographic Gauss-Seidel on the coarse ones (backwards after it): with
//   R = P^T and equal sweep counts a symmetric positive definite preconditioner.
// - Before all that, with a tolerance: a problem whose every region sees one Dirichlet value
//   gets those values, exactly, without a level (constant_regions.hpp).

#include <memory>
#include <vector>

#include "vicc_glyphs/render/grid_problem.hpp"

namespace vicc_glyphs {

struct MultigridOptions {
  int pre_smoothing = 1;        ///< sweeps before the coarse correction
  int post_smoothing = 1;       ///< sweeps after it in reverse order (equal counts: symmetric)
  int intermediate_cycles = 1;  ///< FMG: V-cycles on the levels between the coarsest and
                                ///< the one next to the finest
  /// FMG: V-cycles on the level next to the finest before its solution, interpolated, starts
  /// the finest level: that start is only as good as this solve, and a cycle there costs about
  /// a third of one on the finest level (with 3, most icons need no CG iteration at 512 px).
  int next_to_finest_cycles = 3;
  /// FMG with a tolerance: one V-cycle more on the level next to the finest when the largest
  /// update of its last one exceeded this many tolerances (0: never). Dense curves (waved
  /// contours) leave that solve short of what the finest level's start needs, and the cycle
  /// (a quarter of a CG iteration's instructions, nearer half its time) then saves the
  /// iteration; most plain icons stay below it and pay only the measurement (see
  /// docs/rendering.md).
  double extra_next_to_finest_cycle_above = 3.5;
  int coarsest_size = 16;         ///< coarsen until the larger side is at most this (1..64);
                                  ///< that level is solved directly
  bool record_residuals = false;  ///< record the finest level's residuals and estimates
  /// When the first CG iteration shows slow convergence, deflate the piecewise constants of
  /// the image's pieces (free pixels split at holes and necks of one or two pixels and into
  /// 128 px squares) from CG's directions (see docs/rendering.md): regions behind such necks,
  /// like the ladybug's leg pockets, then converge in fewer iterations.
  bool deflation = true;
  /// With deflation: the free pixels around those where the V-cycle's correction was largest
  /// when the deflation started (the regions that the V-cycle corrects slowest) become pieces
  /// of one pixel each, if they are few; CG then no longer spends iterations on their error
  /// (the ladybug at 512 px: 3 instead of 6; see docs/rendering.md).
  bool singleton_pieces = true;
  /// Symmetric Gauss-Seidel sweeps (forwards and backwards) on the finest level's start around
  /// the pixels whose residual is large, before CG (0: none): FMG's start is poor at a few
  /// spots that P cannot represent (sharp wave tips, curve ends), and the V-cycle reduces them
  /// only about tenfold per iteration (see docs/rendering.md).
  int local_relaxation = 2;
  /// With local relaxation: the sweeps (if more than local_relaxation) when the seeds are
  /// isolated spots, at most one per 256 free pixels (a waved contour's tips and the slits
  /// between its lobes, where Gauss-Seidel needs more than 2 sweeps; the squares' radius is
  /// then 3 instead of 2). A few hundred pixels: far cheaper than the CG iteration that about
  /// 1 in 10 waved glyphs took for want of them (see docs/rendering.md, session 37).
  int isolated_spot_sweeps = 16;
  /// > 0 (the default): iterate on the finest level until the error estimate, the largest
  /// magnitude of the V-cycle's correction B r over the free pixels and channels (colour
  /// units, 0..1), is at most this, at most `max_fine_cycles` times; the estimates are then
  /// always recorded, and that last correction is added to the result. 0: `fine_cycles`
  /// iterations, whatever the error.
  double tolerance = kDefaultTolerance;
  int max_fine_cycles = 50;
  int fine_cycles = 2;  ///< iterations on the finest level when tolerance is 0 (fewer once
                        ///< the correction is below float resolution)
  /// With a tolerance: when every free region's Dirichlet values agree (within half of
  /// ConstantRegions::kDefaultSpread of one value per channel; flat-colour icons, waved or
  /// not), write that value into each region instead of iterating: the exact solution within
  /// that half spread (constant_regions.hpp).
  /// If one region does not qualify, all are iterated as without it. A fixed iteration count
  /// (tolerance 0) always iterates.
  bool constant_regions = true;

  /// About half an 8-bit colour step (1/510); see docs/rendering.md for how the true error
  /// compares.
  static constexpr double kDefaultTolerance = 2e-3;
  /// The coarsest level is factorised densely within its band: (size^2) x size doubles.
  static constexpr int kMaxCoarsestSize = 64;
};

struct MultigridReport {
  int levels = 0;
  int fine_cycles = 0;  ///< CG iterations (one V-cycle each) done on the finest level
  /// FMG's V-cycles on the level next to the finest (next_to_finest_cycles, or one more).
  int next_to_finest_cycles = 0;
  /// With a tolerance: whether the error estimate reached it within max_fine_cycles.
  bool converged = false;
  /// Without a tolerance (fine_cycles): whether the iterations stopped before that count
  /// because the V-cycle's correction fell below float resolution (1e-6): further ones change
  /// no pixel, and in float arithmetic CG would drift away again.
  bool stopped_at_float_resolution = false;
  /// Over the finest level's free pixels and all channels: RMS residual (entry 0 at the FMG
  /// start, entry k after iteration k) and RMS update of iteration k+1 (entry k), with
  /// record_residuals only (they cost arithmetic in the CG's passes); error estimate (largest
  /// magnitude, see tolerance) of the iterate after iteration k (entry k; with a tolerance the
  /// last one is the one that met it), with record_residuals or a tolerance.
  std::vector<double> residuals;
  std::vector<double> error_estimates;
  std::vector<double> updates;
  /// Every free region took its one Dirichlet value (MultigridOptions::constant_regions): no
  /// levels, no iterations, converged.
  bool constant_regions = false;
};

/// Grid sizes of the hierarchy, finest first: each level halves (rounding up) the previous one
/// until the larger side is at most `coarsest_size` (a side of 1 stays 1).
std::vector<std::pair<int, int>> levelSizes(int width, int height, int coarsest_size);

/// Solves grid problems, keeping its working memory between solves (fresh memory costs page
/// faults that can take longer than the solve itself).
class MultigridSolver {
 public:
  MultigridSolver();
  ~MultigridSolver();
  MultigridSolver(const MultigridSolver&) = delete;
  MultigridSolver& operator=(const MultigridSolver&) = delete;

  /// Solves `problem` (1 or 3 channels). Writes width*height*channels values, pixel-major like
  /// GridProblem::values, to `values`. Throws std::invalid_argument on an inconsistent problem
  /// or options.
  void solve(const GridProblem& problem, const MultigridOptions& options,
             std::vector<float>& values, MultigridReport* report);
  /// As above, writing to `values` (room for width*height*channels floats), e.g. straight
  /// into an output cv::Mat.
  void solve(const GridProblem& problem, const MultigridOptions& options, float* values,
             MultigridReport* report);

 private:
  struct Workspaces;
  std::unique_ptr<Workspaces> workspaces_;
};

/// One-off solve with a temporary MultigridSolver.
std::vector<float> solveMultigrid(const GridProblem& problem, const MultigridOptions& options,
                                  MultigridReport* report);

}  // namespace vicc_glyphs
