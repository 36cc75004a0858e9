#include "multigrid_levels.hpp"

#include <algorithm>
#include <tuple>
#include <type_traits>
#include <utility>

namespace vicc_glyphs::multigrid_detail {
namespace {

// A regular operator: every point free with the same stencil; bilinear prolongation. Gives
// the coarse stencil of the parts of a level away from curves and borders.
struct RegularOperator {
  Stencil stencil;
  int stride = 0;
  Stencil row(int) const { return stencil; }
  bool isFree(int) const { return true; }
  int index(int, int) const { return 0; }
};

// One side of a point between two coarse points (an edge point): its coupling to the coarse
// point on that side (direct) and to the two neighbours beside that one (diagonal).
struct EdgeSide {
  float direct, diagonal;
  bool free;  // the coarse point is an unknown (not a Dirichlet pixel)
};

// Weights of an edge point from its row collapsed onto the line through the two coarse points
// (black box multigrid): the neighbours beside a coarse point are taken to move with it and
// those across the line with the edge point itself; the weight of a side is its coupling over
// the collapsed diagonal, which keeps the links to Dirichlet points (a correction is 0 there).
// Where the direct coupling is missing (a cut link, or a coarse point that is not an unknown:
// coarse rows have no couplings to Dirichlet points) the diagonal neighbours lie on the edge
// point's side, not the coarse point's: their couplings go to the diagonal as well, so nothing
// is interpolated across a barrier that runs diagonally between a coarse point and its
// neighbours, and a point without Dirichlet links still interpolates constants exactly.
// Weights never sum to more than 1.
std::pair<float, float> edgeWeights(const EdgeSide& first, const EdgeSide& second,
                                    float collapsed_centre) {
  float denominator = collapsed_centre;
  float weights[2];
  const EdgeSide* sides[2] = {&first, &second};
  for (int k = 0; k < 2; ++k) {
    const float coupling = sides[k]->direct + sides[k]->diagonal;
    if (sides[k]->free && sides[k]->direct < 0.0f && coupling < 0.0f) {
      weights[k] = -coupling;
    } else {
      weights[k] = 0.0f;
      denominator += coupling;
    }
  }
  denominator = std::max(denominator, weights[0] + weights[1]);
  if (!(denominator > 0.0f)) return {0.0f, 0.0f};
  return {weights[0] / denominator, weights[1] / denominator};
}

template <class Op>
void edgeWeightsOfCell(const Op& fine, int i, int j, CellWeights& cell) {
  const int corner = fine.index(2 * i, 2 * j);
  const int x_edge = fine.index(2 * i + 1, 2 * j), y_edge = fine.index(2 * i, 2 * j + 1);
  cell.x_west = cell.x_east = cell.y_north = cell.y_south = 0.0f;
  const bool corner_free = fine.isFree(corner);
  if (fine.isFree(x_edge)) {
    const Stencil a = fine.row(x_edge);
    std::tie(cell.x_west, cell.x_east) =
        edgeWeights({a[kW], a[kNW] + a[kSW], corner_free},
                    {a[kE], a[kNE] + a[kSE], fine.isFree(x_edge + 1)}, a[kN] + a[kC] + a[kS]);
  }
  if (fine.isFree(y_edge)) {
    const Stencil a = fine.row(y_edge);
    std::tie(cell.y_north, cell.y_south) = edgeWeights(
        {a[kN], a[kNW] + a[kNE], corner_free},
        {a[kS], a[kSW] + a[kSE], fine.isFree(y_edge + fine.stride)}, a[kW] + a[kC] + a[kE]);
  }
}

// The centre point of cell I from its own row, over its neighbours: the corners directly, the
// edge points through their weights (those of cells I, I + east and I + south).
template <class Op>
void centreWeightsOfCell(const Op& fine, int i, int j, const CellWeights& south_cell,
                         const CellWeights& east_cell, CellWeights& cell) {
  cell.nw = cell.ne = cell.sw = cell.se = 0.0f;
  const int centre = fine.index(2 * i + 1, 2 * j + 1);
  if (!fine.isFree(centre)) return;
  const Stencil a = fine.row(centre);
  // A free point without links has no equation to interpolate from (1 / 0 would make the
  // weights NaN): its correction stays 0. The assembler makes such pixels Dirichlet pixels.
  if (!(a[kC] > 0.0f)) return;
  const float inverse = 1.0f / a[kC];
  float nw = -(a[kNW] + a[kN] * cell.x_west + a[kW] * cell.y_north) * inverse;
  float ne = -(a[kNE] + a[kN] * cell.x_east + a[kE] * east_cell.y_north) * inverse;
  float sw = -(a[kSW] + a[kS] * south_cell.x_west + a[kW] * cell.y_south) * inverse;
  float se = -(a[kSE] + a[kS] * south_cell.x_east + a[kE] * east_cell.y_south) * inverse;
  nw = std::max(nw, 0.0f), ne = std::max(ne, 0.0f), sw = std::max(sw, 0.0f),
  se = std::max(se, 0.0f);
  const float sum = nw + ne + sw + se;
  const float scale = sum > 1.0f ? 1.0f / sum : 1.0f;
  cell.nw = nw * scale, cell.ne = ne * scale, cell.sw = sw * scale, cell.se = se * scale;
}

// The prolongation weights of coarse point (i, j) on the 3 x 3 fine points around (2i, 2j)
// (its column of P), from the cells whose squares hold them.
template <class Op, class Cells>
Stencil column(const Op& fine, const Cells& cells, int i, int j) {
  if (!fine.isFree(fine.index(2 * i, 2 * j))) return {};
  const CellWeights& c = cells(i, j);
  const CellWeights& w = cells(i - 1, j);
  const CellWeights& n = cells(i, j - 1);
  const CellWeights& nw = cells(i - 1, j - 1);
  return {nw.se, n.y_south, n.sw, w.x_east, 1.0f, c.x_west, w.ne, c.y_north, c.nw};
}

// The forward couplings (centre, east, south-west, south, south-east) of coarse point I = (i, j)
// in R A P: A P e_I on the 7 x 7 fine points around (2i, 2j), then its products with the
// columns of I and of the forward neighbours.
struct ForwardCouplings {
  float centre, east, south_west, south, south_east;
};

template <class Op, class Cells>
ForwardCouplings galerkinCouplings(const Op& fine, const Cells& cells, int i, int j,
                                   int coarse_width, int coarse_height) {
  const auto columnAt = [&](int ci, int cj) -> Stencil {
    if (ci < 0 || cj < 0 || ci >= coarse_width || cj >= coarse_height) return {};
    return column(fine, cells, ci, cj);
  };
  const Stencil own = columnAt(i, j);
  if (own[kC] == 0.0f) return {};
  // Level 0's rows are 5-point stencils, so A P e_I reaches only 2 fine points out there. The
  // products with their corners and with the entries 3 out are +0 (finite, non-negative
  // weights; a sum from +0 never becomes -0) and are left out: the same bits, fewer products.
  constexpr bool kFivePoint = std::is_same_v<Op, FineLevel>;
  constexpr int kReach = kFivePoint ? 2 : 3;
  float applied[7][7] = {};  // A P e_I at fine offsets -3..3 (rows, columns) from (2i, 2j)
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      const float weight = own[(dy + 1) * 3 + dx + 1];
      if (weight == 0.0f) continue;
      const Stencil a = fine.row(fine.index(2 * i + dx, 2 * j + dy));
      for (int ey = -1; ey <= 1; ++ey) {
        for (int ex = -1; ex <= 1; ++ex) {
          if (kFivePoint && ey != 0 && ex != 0) continue;
          applied[3 + dy + ey][3 + dx + ex] += a[(ey + 1) * 3 + ex + 1] * weight;
        }
      }
    }
  }
  const auto coupling = [&](int di, int dj) {
    const Stencil other = columnAt(i + di, j + dj);
    float sum = 0.0f;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int y = 3 + 2 * dj + dy, x = 3 + 2 * di + dx;
        if (x < 3 - kReach || x > 3 + kReach || y < 3 - kReach || y > 3 + kReach) continue;
        sum += other[(dy + 1) * 3 + dx + 1] * applied[y][x];
      }
    }
    return sum;
  };
  return {coupling(0, 0), coupling(1, 0), coupling(-1, 1), coupling(0, 1), coupling(1, 1)};
}

Stencil fullStencil(const ForwardCouplings& f) {
  return {f.south_east, f.south,      f.south_west, f.east,      f.centre,
          f.east,       f.south_west, f.south,      f.south_east};
}

// Marks, in `irregular` (fine layout, ghost border included), the fine points whose row
// differs from `regular`. Level 0 is tested on its link bytes.
void markIrregularRows(const FineLevel& fine, const Stencil&, std::uint8_t* irregular) {
  const int s = fine.stride;
  std::fill_n(irregular, fine.size, 1);
  const std::uint8_t* m = fine.mask.data();
  for (int y = 0; y < fine.height; ++y) {
    for (int p = fine.index(0, y), end = fine.index(fine.width, y); p < end; ++p) {
      irregular[p] =
          (m[p] != kAllLinks) | (((m[p - 1] | m[p + 1] | m[p - s] | m[p + s]) & kFixed) != 0);
    }
  }
}

void markIrregularRows(const CoarseLevel& fine, const Stencil&, std::uint8_t* irregular) {
  for (size_t p = 0; p < fine.size; ++p) irregular[p] = !fine.regular[p];
}

// out[i] = OR of in[step * i + offset + k], k = 0 .. kCount - 1, over positions 0 .. size - 1
// (positions outside count as set).
template <int kCount>
void orWindows(const std::uint8_t* __restrict in, int size, int step, int offset,
               std::uint8_t* __restrict out, int out_count) {
  for (int i = 0; i < out_count; ++i) {
    const int first = step * i + offset;
    if (first >= 0 && first + kCount <= size) {
      std::uint8_t any = 0;
      for (int k = 0; k < kCount; ++k) any |= in[first + k];
      out[i] = any;
    } else {
      std::uint8_t any = 1;  // outside
      for (int k = std::max(first, 0); k < std::min(first + kCount, size); ++k) any |= in[k];
      out[i] = any;
    }
  }
}

// OR of `flags` (rows x columns) over windows: output (i, j) covers kColumns columns from
// step * i + offset and kRows rows from step * j + offset (positions outside count as set).
// Rows first (contiguous ORs of whole rows, which vectorise), then along each row.
template <int kColumns, int kRows>
void dilate(const std::uint8_t* flags, int rows, int columns, int out_rows, int out_columns,
            int step, int column_offset, int row_offset, std::uint8_t* across, std::uint8_t* out,
            int out_stride, int out_offset) {
  for (int j = 0; j < out_rows; ++j) {
    std::uint8_t* __restrict merged = across;
    const int first = step * j + row_offset;
    const bool outside = first < 0 || first + kRows > rows;
    std::fill_n(merged, columns, static_cast<std::uint8_t>(outside));
    for (int y = std::max(first, 0); y < std::min(first + kRows, rows); ++y) {
      const std::uint8_t* __restrict row = flags + static_cast<size_t>(y) * columns;
      for (int x = 0; x < columns; ++x) merged[x] |= row[x];
    }
    orWindows<kColumns>(merged, columns, step, column_offset, out + out_offset + j * out_stride,
                        out_columns);
  }
}

// Marks the coarse cells whose prolongation may differ from the bilinear one (`cells`: a fine
// row in x, y in 2i .. 2i + 2 is irregular; the ghost border and beyond count as irregular)
// and the points whose Galerkin row may differ from the regular one (`galerkin`): an irregular
// fine row around (2i, 2j) (x, y in 2i - 1 .. 2i + 1), or an irregular cell among those the
// columns of I and of its forward neighbours come from (i - 2 .. i + 1, j - 1 .. j + 1).
template <class Op>
void markIrregular(const Op& fine, const Stencil& regular, const CoarseLevel& coarse,
                   std::vector<std::uint8_t>& scratch, std::uint8_t*& cells,
                   std::uint8_t*& galerkin) {
  const int cw = coarse.width, ch = coarse.height;
  const int fine_rows = fine.height + 2, fine_columns = fine.stride;
  const size_t across_size = static_cast<size_t>(fine_columns);
  const size_t grid_size = static_cast<size_t>(cw) * ch;
  scratch.resize(fine.size + across_size + 3 * grid_size + 2 * coarse.size);
  std::uint8_t* irregular = scratch.data();
  std::uint8_t* across = irregular + fine.size;
  std::uint8_t* cell_flags = across + across_size;  // cw x ch, no border
  std::uint8_t* around = cell_flags + grid_size;    // ditto
  std::uint8_t* window = around + grid_size;        // ditto
  cells = window + grid_size;
  galerkin = cells + coarse.size;
  markIrregularRows(fine, regular, irregular);
  // Fine column (row) 2i + k is layout column (row) 2i + k + 1.
  dilate<3, 3>(irregular, fine_rows, fine_columns, ch, cw, 2, 1, 1, across, cell_flags, cw, 0);
  dilate<3, 3>(irregular, fine_rows, fine_columns, ch, cw, 2, 0, 0, across, around, cw, 0);
  dilate<4, 3>(cell_flags, ch, cw, ch, cw, 1, -2, -1, across, window, cw, 0);
  std::fill_n(cells, coarse.size, 1);
  std::fill_n(galerkin, coarse.size, 1);
  for (int j = 0; j < ch; ++j) {
    const size_t row = static_cast<size_t>(j) * cw;
    std::copy_n(cell_flags + row, cw, cells + coarse.index(0, j));
    for (int i = 0; i < cw; ++i) {
      galerkin[coarse.index(i, j)] = around[row + i] | window[row + i];
    }
  }
}

template <class Op>
void coarsenLevel(const Op& fine, const Stencil& regular_fine, Transfer& transfer,
                  CoarseLevel& coarse, std::vector<std::uint8_t>& scratch) {
  const int cw = coarse.width, ch = coarse.height;
  // The regular coarse stencil, from the same computation on a regular operator.
  const RegularOperator regular{regular_fine, 0};
  const auto bilinear = [](int, int) -> const CellWeights& { return kBilinearCell; };
  const Stencil regular_coarse = fullStencil(galerkinCouplings(regular, bilinear, 2, 2, 5, 5));

  std::uint8_t *irregular_cells = nullptr, *irregular_rows = nullptr;
  markIrregular(fine, regular_fine, coarse, scratch, irregular_cells, irregular_rows);
  transfer.resize(coarse.size);
  std::fill(transfer.begin(), transfer.end(), CellWeights{});
  coarse.worked_out_cells.clear();
  for (int j = 0; j < ch; ++j) {
    for (int i = 0; i < cw; ++i) {
      const int c = coarse.index(i, j);
      if (irregular_cells[c]) {
        edgeWeightsOfCell(fine, i, j, transfer[c]);
        coarse.worked_out_cells.push_back(c);
      } else {
        transfer[c] = kBilinearCell;
      }
    }
  }
  for (int j = 0; j < ch; ++j) {
    for (int i = 0; i < cw; ++i) {
      const int c = coarse.index(i, j);
      if (!irregular_cells[c]) continue;
      centreWeightsOfCell(fine, i, j, transfer[c + coarse.stride], transfer[c + 1], transfer[c]);
    }
  }

  const auto cells = [&](int i, int j) -> const CellWeights& {
    return transfer[coarse.index(i, j)];
  };
  for (int j = 0; j < ch; ++j) {
    for (int i = 0; i < cw; ++i) {
      const int c = coarse.index(i, j);
      ForwardCouplings f{regular_coarse[kC], regular_coarse[kE], regular_coarse[kSW],
                         regular_coarse[kS], regular_coarse[kSE]};
      if (irregular_rows[c]) f = galerkinCouplings(fine, cells, i, j, cw, ch);
      coarse.centre[c] = f.centre;
      coarse.inverse_centre[c] = f.centre > 0.0f ? 1.0f / f.centre : 0.0f;
      coarse.east[c] = f.east;
      coarse.south_west[c] = f.south_west;
      coarse.south[c] = f.south;
      coarse.south_east[c] = f.south_east;
    }
  }
  // A row is regular when its forward couplings and those of the neighbours before it (its
  // backward couplings) are; first the forward ones, in the Galerkin flags' place.
  coarse.regular_stencil = regular_coarse;
  std::uint8_t* forward = irregular_rows;
  for (size_t c = 0; c < coarse.size; ++c) {
    forward[c] =
        !irregular_rows[c] ||
        (coarse.centre[c] == regular_coarse[kC] && coarse.east[c] == regular_coarse[kE] &&
         coarse.south_west[c] == regular_coarse[kSW] && coarse.south[c] == regular_coarse[kS] &&
         coarse.south_east[c] == regular_coarse[kSE]);
  }
  const int s = coarse.stride;
  for (int j = 0; j < ch; ++j) {
    for (int c = coarse.index(0, j), end = coarse.index(cw, j); c < end; ++c) {
      coarse.regular[c] =
          forward[c] & forward[c - 1] & forward[c - s] & forward[c - s - 1] & forward[c - s + 1];
    }
  }
}

}  // namespace

void makeFineLevel(const GridProblem& problem, FineLevel& level) {
  level.width = problem.width;
  level.height = problem.height;
  level.stride = problem.width + 2;
  level.size = static_cast<size_t>(level.stride) * (problem.height + 2);
  level.mask.assign(level.size, kFixed);
  // Branch-free (the problem's flags are 0 or 1), so that the loops vectorise.
  const int w = problem.width;
  for (int y = 0; y < problem.height; ++y) {
    std::uint8_t* __restrict out = level.mask.data() + level.index(0, y);
    const std::uint8_t* right = problem.couples_right.data() + y * w;
    const std::uint8_t* down = problem.couples_down.data() + y * w;
    const std::uint8_t* fixed = problem.fixed.data() + y * w;
    for (int x = 0; x < w; ++x) {
      out[x] = static_cast<std::uint8_t>(fixed[x] * kFixed | right[x] * kRight | down[x] * kDown);
    }
    for (int x = 1; x < w; ++x) out[x] |= static_cast<std::uint8_t>(right[x - 1] * kLeft);
    if (y == 0) continue;
    const std::uint8_t* up = problem.couples_down.data() + (y - 1) * w;
    for (int x = 0; x < w; ++x) out[x] |= static_cast<std::uint8_t>(up[x] * kUp);
  }
}

void resizeCoarseLevel(int width, int height, CoarseLevel& coarse) {
  const size_t size = static_cast<size_t>(width + 2) * (height + 2);
  if (coarse.width == width && coarse.height == height && coarse.size == size) return;
  coarse.width = width;
  coarse.height = height;
  coarse.stride = width + 2;
  coarse.size = size;
  for (auto* field : {&coarse.centre, &coarse.inverse_centre, &coarse.east, &coarse.south_west,
                      &coarse.south, &coarse.south_east}) {
    field->assign(size, 0.0f);
  }
  coarse.regular.assign(size, 0);
}

void coarsen(const FineLevel& fine, Transfer& transfer, CoarseLevel& coarse,
             std::vector<std::uint8_t>& scratch) {
  coarsenLevel(fine, kFineRegularStencil, transfer, coarse, scratch);
}

void coarsen(const CoarseLevel& fine, Transfer& transfer, CoarseLevel& coarse,
             std::vector<std::uint8_t>& scratch) {
  coarsenLevel(fine, fine.regular_stencil, transfer, coarse, scratch);
}

}  // namespace vicc_glyphs::multigrid_detail
