#pragma once
// The solver layout of one multigrid level and the curve-aware transfer rules between two
// levels (internal to the renderer; used by multigrid.cpp).

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "vicc_glyphs/render/grid_problem.hpp"
#include "vicc_glyphs/render/pixel_buffer.hpp"

namespace vicc_glyphs::multigrid_detail {

// Per-pixel link bits: which of the four neighbours the pixel is coupled to, plus the
// Dirichlet flag. One byte per pixel keeps the smoother's memory traffic low.
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

// Normalised bilinear weights (9, 3, 3, 1) / 16 of the four coarse sources of a fine pixel:
// the coarse cell containing it, its horizontal, vertical and diagonal neighbour, for each
// combination of usable sources (bit 0: horizontal, 1: vertical, 2: diagonal, 3: own cell).
struct ProlongationWeights {
  float near, x, y, xy;
};

inline constexpr int kNear = 8;
inline constexpr std::uint8_t kNoSources = 255;  // nothing to interpolate (a Dirichlet pixel)

constexpr ProlongationWeights prolongationWeights(int usable) {
  const float near = usable & kNear ? 9.0f : 0.0f;
  const float x = usable & 1 ? 3.0f : 0.0f, y = usable & 2 ? 3.0f : 0.0f;
  const float xy = usable & 4 ? 1.0f : 0.0f;
  const float total = near + x + y + xy;
  if (total == 0.0f) return {0.0f, 0.0f, 0.0f, 0.0f};
  return {near / total, x / total, y / total, xy / total};
}

template <size_t... I>
constexpr std::array<ProlongationWeights, sizeof...(I)> makeProlongationTable(
    std::index_sequence<I...>) {
  return {prolongationWeights(static_cast<int>(I))...};
}

inline constexpr std::array<ProlongationWeights, 16> kProlongation =
    makeProlongationTable(std::make_index_sequence<16>());

// One level in solver layout: a one-pixel ghost border (Dirichlet, unlinked) around the grid
// so that no loop needs border cases; values are pixel-major (C floats per pixel).
struct Level {
  int width = 0;
  int height = 0;
  int stride = 0;
  size_t size = 0;
  render_detail::PixelVector<std::uint8_t> mask;
  std::vector<int> coarse_x, coarse_x_neighbour;  // bilinear prolongation sources per column
  std::vector<int> coarse_y, coarse_y_neighbour;  // ... and per row
  // Per pixel: the coarse sources (kProlongation index) used to interpolate a solution (FMG)
  // and a correction (V-cycle); see prolongationSources.
  render_detail::PixelVector<std::uint8_t> solution_sources;
  render_detail::PixelVector<std::uint8_t> correction_sources;
  // Per pixel: the connected component of free pixels (over links) it belongs to, -1 at
  // Dirichlet pixels and in the ghost border; see labelFreeComponents.
  std::vector<int> component;
  int component_count = 0;
  // The free pixels linked to Dirichlet pixels and how many such links each has: all that
  // ties a component's values down (A = graph Laplacian + this diagonal).
  struct Pinned {
    int pixel;
    float links;
  };
  std::vector<Pinned> pinned;
  render_detail::PixelVector<std::uint8_t> pending;  // scratch of prolongationSources
  std::vector<int> irregular;                        // ditto

  int index(int x, int y) const { return (y + 1) * stride + x + 1; }
};

/// Converts `problem` into `level` (reusing its memory).
void makeLevel(const GridProblem& problem, Level& level);

/// Labels the connected components of the free pixels of `level` (level.component) and
/// lists its pinned pixels. The Laplacian restricted to the free pixels is block-diagonal over
/// the components; the solver deflates each one's constant (see multigrid.cpp).
void labelFreeComponents(Level& level);

/// Cell-centred bilinear interpolation: fine cell i lies a quarter cell from coarse cell i/2
/// towards its neighbour i/2 -/+ 1 (clamped at the border).
void prolongationTable(int fine, int coarse, std::vector<int>& near, std::vector<int>& neighbour);

// Which coarse sources each free fine pixel interpolates from. A neighbour source counts only
// if the fine link from the pixel towards it and the coarse link between it and the pixel's
// own coarse cell are intact, so values do not leak across a curve (plain bilinear weights
// mix the two sides' colours into every pixel near a curve). A correction is moreover never
// taken from a coarse Dirichlet cell: its correction is 0 only because that cell is fixed on
// the coarse grid. The restriction is the transpose of the correction prolongation.
// Away from curves and borders all four sources are usable; only the pixels near a fine or
// coarse pixel that is not fully linked are worked out one by one.
void prolongationSources(Level& fine, const Level& coarse);

}  // namespace vicc_glyphs::multigrid_detail
