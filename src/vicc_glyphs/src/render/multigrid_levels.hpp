#pragma once
// The operators of the multigrid hierarchy (internal to the renderer; used by multigrid.cpp and
// the tests). Level 0 is the GridProblem's 5-point graph Laplacian over its free pixels, kept as
// one link byte per pixel; every coarser level is the Galerkin product R A P of the level above,
// with an operator-dependent prolongation P (black box multigrid: Alcouffe, Brandt, Dendy and
// Painter 1981; Dendy 1982) and R = P^T. Coarse point (i, j) is fine point (2i, 2j)
// (vertex-centred coarsening); the coarse operators are 9-point stencils.
//
// Why Galerkin: a coarse problem rasterised again from the curves couples a region that reaches
// its Dirichlet pixels only through gaps in barriers more weakly or more strongly than the fine
// problem does, differently on every level, and the coarse correction of that region's smooth
// error is then off by that factor. R A P has, for every coarse vector v, exactly the energy of
// P v on the fine grid, gaps included, and P follows the links (it never interpolates across a
// cut link), so the coarse grids see the barriers and the gaps as the fine grid does.

#include <array>
#include <cstdint>
#include <vector>

#include "vicc_glyphs/render/grid_problem.hpp"
#include "vicc_glyphs/render/pixel_buffer.hpp"

namespace vicc_glyphs::multigrid_detail {

// Per-pixel link bits of level 0: which of the four neighbours the pixel is coupled to, plus
// the Dirichlet flag. One byte per pixel keeps the smoother's memory traffic low.
inline constexpr std::uint8_t kLeft = 1, kRight = 2, kUp = 4, kDown = 8, kFixed = 16;
inline constexpr std::uint8_t kAllLinks = kLeft | kRight | kUp | kDown;

struct LinkWeights {
  float left, right, up, down, inv_degree;
};

constexpr LinkWeights linkWeights(int links) {
  const float l = links & kLeft ? 1.0f : 0.0f, r = links & kRight ? 1.0f : 0.0f;
  const float u = links & kUp ? 1.0f : 0.0f, d = links & kDown ? 1.0f : 0.0f;
  const float degree = l + r + u + d;
  return {l, r, u, d, degree > 0.0f ? 1.0f / degree : 0.0f};
}

inline constexpr LinkWeights kWeights[16] = {
    linkWeights(0),  linkWeights(1),  linkWeights(2),  linkWeights(3),
    linkWeights(4),  linkWeights(5),  linkWeights(6),  linkWeights(7),
    linkWeights(8),  linkWeights(9),  linkWeights(10), linkWeights(11),
    linkWeights(12), linkWeights(13), linkWeights(14), linkWeights(15)};

// One row of a level's matrix (over its free points) as a 3 x 3 stencil, row-major: entry
// (dy + 1) * 3 + (dx + 1) couples the point to its neighbour (x + dx, y + dy). All zero at
// Dirichlet points, outside the grid and in the ghost border.
using Stencil = std::array<float, 9>;
inline constexpr int kNW = 0, kN = 1, kNE = 2, kW = 3, kC = 4, kE = 5, kSW = 6, kS = 7, kSE = 8;

// Level 0: the GridProblem's links, with a one-pixel ghost border (Dirichlet, unlinked) around
// the grid so that no loop needs border cases.
struct FineLevel {
  int width = 0;
  int height = 0;
  int stride = 0;
  size_t size = 0;
  render_detail::PixelVector<std::uint8_t> mask;

  int index(int x, int y) const { return (y + 1) * stride + x + 1; }
  bool isFree(int p) const { return !(mask[p] & kFixed); }
  // Degree on the diagonal (links to Dirichlet pixels included), -1 per link to a free pixel.
  Stencil row(int p) const {
    const std::uint8_t m = mask[p];
    if (m & kFixed) return {};
    const LinkWeights& w = kWeights[m & kAllLinks];
    const auto coupling = [&](float link, int q) { return mask[q] & kFixed ? 0.0f : -link; };
    const int s = stride;
    return {0.0f,
            coupling(w.up, p - s),
            0.0f,
            coupling(w.left, p - 1),
            w.left + w.right + w.up + w.down,
            coupling(w.right, p + 1),
            0.0f,
            coupling(w.down, p + s),
            0.0f};
  }
};

// A coarse level: the Galerkin operator as the diagonal and the couplings to the east,
// south-west, south and south-east neighbours (the other four are those neighbours' couplings
// back: the operator is symmetric by construction). Zero rows at points that are not unknowns
// (their fine point is a Dirichlet pixel) and in the ghost border, so the smoother leaves them
// at 0 without a branch.
struct CoarseLevel {
  int width = 0;
  int height = 0;
  int stride = 0;
  size_t size = 0;
  render_detail::PixelVector<float> centre, inverse_centre, east, south_west, south, south_east;
  // The stencil of the parts away from curves and borders, and per point whether its row is
  // that one (the smoother's fast path; 0 in the ghost border).
  Stencil regular_stencil{};
  render_detail::PixelVector<std::uint8_t> regular;
  // The cells (indices like the points) whose prolongation weights from this level to the finer
  // one were worked out point by point, in increasing order; every other cell's are
  // kBilinearCell.
  std::vector<int> worked_out_cells;

  int index(int x, int y) const { return (y + 1) * stride + x + 1; }
  bool isFree(int p) const { return centre[p] > 0.0f; }
  Stencil row(int p) const {
    const int s = stride;
    return {south_east[p - s - 1], south[p - s], south_west[p - s + 1],
            east[p - 1],           centre[p],    east[p],
            south_west[p],         south[p],     south_east[p]};
  }
};

// The prolongation from coarse cell I = (i, j) to the fine points of its square: (2i, 2j) takes
// I's value; the x-edge point (2i + 1, 2j) interpolates between I and I + east, the y-edge point
// (2i, 2j + 1) between I and I + south, the centre point (2i + 1, 2j + 1) between the four
// corners I, I + east, I + south, I + south-east. Zero weights for fine points that are
// Dirichlet pixels or outside the grid. Indexed like the coarse level (ghost cells all zero).
struct CellWeights {
  float x_west, x_east, y_north, y_south, nw, ne, sw, se;
};
inline constexpr CellWeights kBilinearCell{0.5f, 0.5f, 0.5f, 0.5f, 0.25f, 0.25f, 0.25f, 0.25f};

using Transfer = render_detail::PixelVector<CellWeights>;

/// Converts `problem` into `level` (reusing its memory).
void makeFineLevel(const GridProblem& problem, FineLevel& level);

/// Sizes `coarse` for a width x height grid; the ghost border is zero (coarsen() writes the
/// rest).
void resizeCoarseLevel(int width, int height, CoarseLevel& coarse);

/// Builds the operator-dependent prolongation from `coarse` (sized, operator not yet set) to
/// `fine`, and then `coarse`'s operator R A P and its regular stencil and flags. Where a
/// point's neighbourhood is regular (the 5-point Laplacian on level 0, `fine.regular_stencil`
/// on a coarse level) the result is the regular one, computed once; only the rest is worked
/// out point by point. `scratch` holds per-point flags between calls.
void coarsen(const FineLevel& fine, Transfer& transfer, CoarseLevel& coarse,
             std::vector<std::uint8_t>& scratch);
void coarsen(const CoarseLevel& fine, Transfer& transfer, CoarseLevel& coarse,
             std::vector<std::uint8_t>& scratch);

/// The regular stencil of level 0: the 5-point Laplacian.
inline constexpr Stencil kFineRegularStencil{0, -1, 0, -1, 4, -1, 0, -1, 0};

}  // namespace vicc_glyphs::multigrid_detail
