// The renderer's start on PACEMOD's output with isolated spots where FMG's start is poor and
// Gauss-Seidel needs more than the 2 sweeps that suffice elsewhere: single Dirichlet pixels of
// a colour between the two sides. Until session 43 the rasteriser made such pixels itself (the
// mean of both colours where a wave's corner touched a line of pixel centres, or a slanted edge
// ran through one); it no longer does, so the test sets a few. Measured on a real waved icon,
// against the direct solve of the same grid problem.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../render/direct_reference_solve.hpp"
#include "vicc_glyphs/io/load.hpp"
#include "vicc_glyphs/pacemod/curve_selection.hpp"
#include "vicc_glyphs/pacemod/periodic_waves.hpp"
#include "vicc_glyphs/render/grid_problem.hpp"
#include "vicc_glyphs/render/multigrid.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

TEST(WavedGlyphSolveTest, MoreSweepsAtIsolatedSpotsSaveTheCgIterationOfARectangleWavedStar) {
  DiffusionCurveImage image =
      loadDiffusionCurves(std::string(VICC_GLYPHS_DATA_DIR) + "/icons/star.svg", 512);
  // 8 waves per 10 mm, 1.2 mm on a 50 mm glyph at 512 px.
  applyWaves(image, selectCurves(image, {}), WaveSpec{Waveform::Rectangle, 0.8, 1.2}, 50.0);
  GridProblem problem = assembleColorProblem(image, 512, 512, 1.0, Color::Zero());
  int fixed = 0, grey = 0;
  for (int p = 0; p < problem.pixelCount(); ++p) {
    if (!problem.fixed[p] || ++fixed % 1000 != 0) continue;
    for (int c = 0; c < 3; ++c) problem.values[3 * p + c] = 0.5f;
    ++grey;
  }
  ASSERT_GE(grey, 10);
  const std::vector<float> direct = solveDirect(problem);

  // The solver's own path (the flat star's regions would take their colours without it).
  MultigridOptions sixteen_sweeps;
  sixteen_sweeps.constant_regions = false;
  MultigridOptions two_sweeps = sixteen_sweeps;
  two_sweeps.isolated_spot_sweeps = 0;  // the 2 sweeps of local_relaxation everywhere
  MultigridReport before, after;
  const std::vector<float> before_values = solveMultigrid(problem, two_sweeps, &before);
  const std::vector<float> after_values = solveMultigrid(problem, sixteen_sweeps, &after);
  ASSERT_TRUE(before.converged);
  ASSERT_TRUE(after.converged);
  EXPECT_EQ(before.fine_cycles, 1);
  EXPECT_EQ(after.fine_cycles, 0);
  // The start itself is better, not just the estimate: the FMG start's estimate halves.
  EXPECT_LT(after.error_estimates.front(), 0.6 * before.error_estimates.front());
  // Both within the tolerance of the direct solve.
  EXPECT_LT(maxAbsoluteError(before_values, direct), MultigridOptions::kDefaultTolerance);
  EXPECT_LT(maxAbsoluteError(after_values, direct), MultigridOptions::kDefaultTolerance);
}

}  // namespace
}  // namespace pacemod
}  // namespace vicc_glyphs
