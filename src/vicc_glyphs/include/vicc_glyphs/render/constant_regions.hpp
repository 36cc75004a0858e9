#pragma once
// The exact solution of a GridProblem whose every free region sees one Dirichlet value.
//
// A free region (free pixels joined by links) is decoupled from every other: its solution
// depends only on the Dirichlet pixels it is linked to. When those carry one value c, u = c
// satisfies every equation of the region (sum over links of u_p - u_q = 0), and it is the only
// solution since the region reaches a Dirichlet pixel. When they differ by at most a spread s
// per channel, the discrete maximum principle (the solution is a weighted mean of those values)
// puts the solution within s / 2 of the middle of their range. Flat-colour icons, waved or
// inflated, are such problems: no iteration is needed, and the result is exact instead of
// within the multigrid tolerance.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "vicc_glyphs/render/grid_problem.hpp"

namespace vicc_glyphs {

class ConstantRegions {
 public:
  /// Far below an 8-bit colour step (1/255) and the multigrid tolerance (2e-3): colour points
  /// of one colour interpolated along a curve differ only by round-off.
  static constexpr float kDefaultSpread = 1e-5f;

  /// If every free region is linked to at least one Dirichlet pixel and all its Dirichlet
  /// values lie within half the `spread` (per channel) of one value (the first Dirichlet value
  /// of that colour in raster order), writes the solution to `values` (width * height *
  /// channels floats, pixel-major like GridProblem::values: the Dirichlet values, and at each
  /// free pixel that value, within half the spread of the exact solution) and returns true.
  /// Otherwise (also for more than kMaxColors such colours) returns false,
  /// as soon as it meets two colours in one region or too many colours (a gradient), leaving
  /// `values` untouched; also for a problem with links across the grid's border. The problem must
  /// be consistent (the solver validates it first).
  bool solve(const GridProblem& problem, float spread, float* values);

  static constexpr std::size_t kMaxColors = 64;

 private:
  using Color3 = std::array<float, 3>;
  bool identifyColors(const GridProblem& problem, float spread);
  bool propagate(const GridProblem& problem);
  bool fillRemaining(const GridProblem& problem);

  std::vector<Color3> colors_;     ///< the distinct Dirichlet values; id k is colors_[k - 1]
  std::vector<std::uint8_t> ids_;  ///< per pixel its colour id, 0: none yet
  std::vector<int> queue_;
};

}  // namespace vicc_glyphs
