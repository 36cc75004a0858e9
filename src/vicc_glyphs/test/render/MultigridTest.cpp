#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>
#if defined(__SSE__)
#include <xmmintrin.h>
#endif

#include "direct_reference_solve.hpp"
#include "sample_images.hpp"
#include "vicc_glyphs/io/load.hpp"
#include "vicc_glyphs/render/multigrid.hpp"
#include "vicc_glyphs/render/renderer.hpp"

namespace vicc_glyphs {
namespace {

struct Comparison {
  double mae = 0.0;
  MultigridReport report;
};

GridProblem colorProblem(const DiffusionCurveImage& image) {
  return assembleColorProblem(image, image.width, image.height, 1.0, Color::Zero());
}

// The defaults with every problem iterated: flat-colour samples would otherwise take their
// exact constants without a multigrid level (ConstantRegionsTest covers that path).
MultigridOptions iterated() {
  MultigridOptions options;
  options.constant_regions = false;
  return options;
}

Comparison compareWithDirect(const DiffusionCurveImage& image, const MultigridOptions& options) {
  const GridProblem problem = colorProblem(image);
  Comparison comparison;
  const std::vector<float> multigrid = solveMultigrid(problem, options, &comparison.report);
  comparison.mae = meanAbsoluteError(multigrid, solveDirect(problem));
  return comparison;
}

class MultigridVersusDirectTest
    : public ::testing::TestWithParam<std::pair<std::string, DiffusionCurveImage>> {};

TEST_P(MultigridVersusDirectTest, DefaultToleranceMatchesTheDirectSolve) {
  const Comparison result = compareWithDirect(GetParam().second, iterated());
  EXPECT_TRUE(result.report.converged) << GetParam().first;
  EXPECT_LE(result.mae, 0.001) << GetParam().first;
  EXPECT_GT(result.report.levels, 4);
}

TEST_P(MultigridVersusDirectTest, InterpolatedCoarseSolutionAloneIsFarOff) {
  // FMG without a single smoothing sweep: shows the comparison can fail.
  MultigridOptions options;
  options.intermediate_cycles = 0;
  options.next_to_finest_cycles = 0;
  options.fine_cycles = 0;
  options.tolerance = 0.0;
  EXPECT_GT(compareWithDirect(GetParam().second, options).mae, 0.005) << GetParam().first;
}

// Odd and non-square sizes exercise the ceil-halving of the hierarchy.
INSTANTIATE_TEST_SUITE_P(
    SampleImages, MultigridVersusDirectTest,
    ::testing::Values(std::pair{std::string("line"), twoColourLineImage(160, 120)},
                      std::pair{std::string("circle"), circleImage(201, 157)},
                      std::pair{std::string("gradient_circle"), gradientCircleImage(200, 200)},
                      std::pair{std::string("barrier"), barrierImage(192, 128)},
                      std::pair{std::string("icon_like"), iconLikeImage(256, 256)}),
    [](const auto& info) { return info.param.first; });

MultigridReport fixedIterations(const DiffusionCurveImage& image, int iterations,
                                int local_relaxation = MultigridOptions().local_relaxation) {
  MultigridOptions options;
  options.local_relaxation = local_relaxation;
  options.tolerance = 0.0;
  options.fine_cycles = iterations;
  options.record_residuals = true;
  MultigridReport report;
  solveMultigrid(colorProblem(image), options, &report);
  return report;
}

TEST(MultigridTest, ErrorToleranceStopsTheIterationsAndIsReported) {
  MultigridOptions options;
  options.tolerance = 1e-5;
  options.record_residuals = true;  // the rms residuals are recorded only when asked for
  const DiffusionCurveImage image = iconLikeImage(256, 256);
  const Comparison converged = compareWithDirect(image, options);
  EXPECT_TRUE(converged.report.converged);
  const std::vector<double>& e = converged.report.error_estimates;
  // One estimate per iterate: the FMG start and each iteration's result.
  ASSERT_EQ(e.size(), static_cast<size_t>(converged.report.fine_cycles) + 1);
  ASSERT_GE(e.size(), 2u);
  EXPECT_LE(e.back(), 1e-5);
  EXPECT_GT(e[e.size() - 2], 1e-5);  // it stopped at the first iterate below the tolerance
  EXPECT_EQ(converged.report.residuals.size(), e.size());
  EXPECT_LE(converged.mae, 2e-5);
  // Too few iterations allowed: reported as not converged.
  options.max_fine_cycles = 1;
  const Comparison capped = compareWithDirect(image, options);
  EXPECT_FALSE(capped.report.converged);
  EXPECT_EQ(capped.report.fine_cycles, 1);
  EXPECT_GT(capped.mae, converged.mae);
}

TEST(MultigridTest, FixedIterationsIgnoreTheTolerance) {
  const MultigridReport report = fixedIterations(iconLikeImage(128, 128), 3);
  EXPECT_EQ(report.fine_cycles, 3);
  EXPECT_FALSE(report.converged);
  EXPECT_EQ(report.residuals.size(), 4u);
  EXPECT_EQ(report.updates.size(), 3u);
}

TEST(MultigridTest, ErrorEstimateFallsTenfoldPerIterationForClosedCurves) {
  // The V-cycle-preconditioned CG's rate, from FMG's start as it is: the local relaxation of
  // the start (LocalRelaxationTest) removes its few bad spots, after which the first iteration
  // has less to gain (7x here).
  const MultigridReport report = fixedIterations(gradientCircleImage(256, 256), 4, 0);
  const std::vector<double>& e = report.error_estimates;
  ASSERT_EQ(e.size(), 4u);
  EXPECT_GT(e[0], 1e-4);  // the FMG start is not already converged
  for (size_t k = 1; k < e.size(); ++k) EXPECT_LT(e[k], 0.1 * e[k - 1]) << "iteration " << k;
}

TEST(MultigridTest, ErrorEstimateKeepsFallingWithBarriersAndOpenCurveEnds) {
  // Curve ends and barrier tips are where the coarse grids see the geometry least well.
  const MultigridReport report = fixedIterations(iconLikeImage(256, 256), 6);
  const std::vector<double>& e = report.error_estimates;
  ASSERT_GE(e.size(), 4u);
  // Fewer than the 6 asked for only where the correction fell below float resolution.
  if (e.size() < 6u) {
    EXPECT_TRUE(report.stopped_at_float_resolution);
  }
  for (size_t k = 1; k < e.size(); ++k) EXPECT_LT(e[k], 0.5 * e[k - 1]) << "iteration " << k;
}

// Far more iterations than float arithmetic can use: CG used to run on past machine precision,
// lose its orthogonality and drift away again (the virus icon, 100 cycles: grey blocks up to
// 11/255 in its white background). It stops once the correction is below float resolution.
TEST(MultigridTest, AFixedCountStopsAtFloatResolutionInsteadOfDrifting) {
  const GridProblem problem = colorProblem(iconLikeImage(256, 256));
  MultigridOptions many;
  many.tolerance = 0.0;
  many.fine_cycles = 100;
  MultigridReport report;
  const std::vector<float> solved = solveMultigrid(problem, many, &report);
  EXPECT_TRUE(report.stopped_at_float_resolution);
  EXPECT_LT(report.fine_cycles, 20);
  EXPECT_LT(meanAbsoluteError(solved, solveDirect(problem)), 1e-5);
  MultigridOptions tight;  // the default tolerance's answer, to 8-bit precision
  const std::vector<float> reference = solveMultigrid(problem, tight, nullptr);
  float largest = 0.0f;
  for (size_t i = 0; i < solved.size(); ++i) {
    largest = std::max(largest, std::abs(solved[i] - reference[i]));
  }
  EXPECT_LT(largest, 1.0f / 255.0f);
}

TEST(MultigridTest, RejectsInconsistentProblemsAndOptions) {
  const GridProblem valid = colorProblem(circleImage(64, 64));
  EXPECT_NO_THROW(solveMultigrid(valid, {}, nullptr));
  GridProblem short_values = valid;
  short_values.values.pop_back();
  EXPECT_THROW(solveMultigrid(short_values, {}, nullptr), std::invalid_argument);
  GridProblem two_channels = valid;
  two_channels.channels = 2;
  EXPECT_THROW(solveMultigrid(two_channels, {}, nullptr), std::invalid_argument);
  EXPECT_THROW(solveMultigrid(GridProblem{}, {}, nullptr), std::invalid_argument);
  MultigridOptions options;
  options.coarsest_size = MultigridOptions::kMaxCoarsestSize + 1;  // too big to factorise
  EXPECT_THROW(solveMultigrid(valid, options, nullptr), std::invalid_argument);
  options.coarsest_size = 0;
  EXPECT_THROW(solveMultigrid(valid, options, nullptr), std::invalid_argument);
}

// Where FMG's solve next to the finest level falls short of what the finest start needs (many
// icons, most waved ones), one more V-cycle there (a quarter of an iteration's cost) saves the
// CG iteration.
// Smooth images stop below the threshold and keep their 3 cycles; a fixed count never adds.
TEST(MultigridTest, AnExtraCycleNextToTheFinestLevelSavesTheIterationOfDenseCurves) {
  // The bell icon at 512 px (its curves are dense enough; so are most waved icons').
  const GridProblem problem =
      colorProblem(loadDiffusionCurves(std::string(VICC_GLYPHS_DATA_DIR) + "/icons/bell.svg", 512));
  const std::vector<float> direct = solveDirect(problem);
  MultigridOptions never = iterated();
  never.extra_next_to_finest_cycle_above = 0.0;
  MultigridReport with, without;
  const std::vector<float> extra = solveMultigrid(problem, iterated(), &with);
  solveMultigrid(problem, never, &without);
  EXPECT_EQ(with.next_to_finest_cycles, 4);
  EXPECT_EQ(without.next_to_finest_cycles, 3);
  EXPECT_LT(with.fine_cycles, without.fine_cycles);
  EXPECT_TRUE(with.converged);
  EXPECT_LT(maxAbsoluteError(extra, direct), MultigridOptions::kDefaultTolerance);

  MultigridReport smooth;
  solveMultigrid(colorProblem(circleImage(512, 512)), iterated(), &smooth);
  EXPECT_EQ(smooth.next_to_finest_cycles, 3);

  MultigridOptions fixed;
  fixed.tolerance = 0.0;
  fixed.fine_cycles = 1;
  MultigridReport counted;
  solveMultigrid(problem, fixed, &counted);
  EXPECT_EQ(counted.next_to_finest_cycles, 3);

  MultigridOptions negative;
  negative.extra_next_to_finest_cycle_above = -1.0;
  EXPECT_THROW(solveMultigrid(problem, negative, nullptr), std::invalid_argument);
  negative.extra_next_to_finest_cycle_above = std::nan("");
  EXPECT_THROW(solveMultigrid(problem, negative, nullptr), std::invalid_argument);
}

TEST(MultigridTest, LevelSizesHalveRoundingUp) {
  const auto sizes = levelSizes(201, 50, 4);
  ASSERT_GE(sizes.size(), 2u);
  EXPECT_EQ(sizes[1], std::make_pair(101, 25));
  EXPECT_LE(std::max(sizes.back().first, sizes.back().second), 4);
  const auto thin = levelSizes(1000, 1, 4);  // thin images coarsen along their long side
  EXPECT_EQ(thin.back(), std::make_pair(4, 1));
}

TEST(MultigridTest, ThinImageConverges) {
  DiffusionCurveImage image{1000, 1, {}};
  image.curves.push_back(lineCurve({100.2, -2}, {100.2, 3}, Color(1, 0, 0), Color(0, 0, 1)));
  image.curves.push_back(lineCurve({900.2, 3}, {900.2, -2}, Color(0, 1, 0), Color(0, 1, 0)));
  MultigridOptions options;
  options.coarsest_size = 4;
  const GridProblem problem = colorProblem(image);
  EXPECT_LE(meanAbsoluteError(solveMultigrid(problem, options, nullptr), solveDirect(problem)),
            1e-3);
}

#if defined(__SSE__)
// Leaves freed heap blocks of many sizes full of denormal floats, as a process's heap can be after
// other work (a freed block's pointer bits read as floats are denormals too).
void leaveDenormalsInFreedHeap() {
  std::vector<std::unique_ptr<float[]>> blocks;
  for (size_t floats = 16; floats <= 65536; floats += floats / 4 + 16) {
    blocks.emplace_back(new float[floats]);
    std::fill_n(blocks.back().get(), floats, 1e-40f);
  }
}

// A colour pixel is a vector of four floats, one of them padding. A padding lane left as the
// allocation found it carried denormals through every level's arithmetic: the same image, but
// the V-cycles about 10x slower in about half the runs (by address layout). The MXCSR's sticky
// denormal-operand flag shows whether any SSE operation of the solve saw one.
TEST(MultigridTest, TheColourSolveSeesNoDenormalsLeftInTheHeap) {
  const GridProblem problem = colorProblem(iconLikeImage(256, 256));
  for (int coarsest_size : {4, 8, 16}) {
    MultigridOptions options;
    options.coarsest_size = coarsest_size;
    leaveDenormalsInFreedHeap();
    const unsigned saved = _mm_getcsr();
    _mm_setcsr(saved & ~0x3fu);  // clear the sticky exception flags
    MultigridReport report;
    solveMultigrid(problem, options, &report);
    const unsigned flags = _mm_getcsr();
    _mm_setcsr(saved);
    EXPECT_EQ(flags & 0x2u, 0u) << "denormal operand, coarsest size " << coarsest_size;
    EXPECT_TRUE(report.converged);
  }
}
#endif

}  // namespace
}  // namespace vicc_glyphs
