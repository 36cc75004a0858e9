#include "multigrid_levels.hpp"

#include <algorithm>

namespace vicc_glyphs::multigrid_detail {
namespace {

// The sources of the free fine pixel p = (x, y).
void pixelSources(Level& fine, const Level& coarse, int x, int y) {
  const int p = fine.index(x, y);
  const std::uint8_t m = fine.mask[p];
  if (m & kFixed) return;
  const int cy = fine.coarse_y[y], ny = fine.coarse_y_neighbour[y];
  const bool down = y % 2;  // the vertical neighbour source lies below
  const std::uint8_t towards_y = down ? kDown : kUp;
  const int step_y = down ? fine.stride : -fine.stride;
  const int cx = fine.coarse_x[x], nx = fine.coarse_x_neighbour[x];
  const bool right = x % 2;
  const int step_x = right ? 1 : -1;
  const std::uint8_t towards_x = right ? kRight : kLeft;
  const int a = coarse.index(cx, cy), b = coarse.index(nx, cy);
  const int d = coarse.index(cx, ny), e = coarse.index(nx, ny);
  const bool use_x = (m & towards_x) && (coarse.mask[std::min(a, b)] & kRight);
  const bool use_y = (m & towards_y) && (coarse.mask[std::min(a, d)] & kDown);
  const bool use_xy =
      (use_x && (fine.mask[p + step_x] & towards_y) && (coarse.mask[std::min(b, e)] & kDown)) ||
      (use_y && (fine.mask[p + step_y] & towards_x) && (coarse.mask[std::min(d, e)] & kRight));
  const int usable = use_x | use_y << 1 | use_xy << 2;
  // A pixel cut off from both its siblings in the coarse cell lies on the other side of a
  // curve through that cell than the cell's centre, most likely.
  const bool near_same_side = (m & (right ? kLeft : kRight)) || (m & (down ? kUp : kDown));
  const bool use_near = near_same_side || usable == 0;
  fine.solution_sources[p] = static_cast<std::uint8_t>(usable | (use_near ? kNear : 0));
  const auto free = [&](int cell) { return !(coarse.mask[cell] & kFixed); };
  const bool near_correction = near_same_side && free(a);
  const int correction = (use_x && free(b)) | (use_y && free(d)) << 1 | (use_xy && free(e)) << 2 |
                         near_correction << 3;
  fine.correction_sources[p] = correction ? static_cast<std::uint8_t>(correction) : kNoSources;
}
}  // namespace

void makeLevel(const GridProblem& problem, Level& level) {
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

void labelFreeComponents(Level& level) {
  level.component.assign(level.size, -1);
  level.component_count = 0;
  level.pinned.clear();
  std::vector<int> stack;
  const int s = level.stride;
  for (int y = 0; y < level.height; ++y) {
    for (int x = 0; x < level.width; ++x) {
      const int start = level.index(x, y);
      if ((level.mask[start] & kFixed) || level.component[start] >= 0) continue;
      const int label = level.component_count++;
      level.component[start] = label;
      stack.assign(1, start);
      while (!stack.empty()) {
        const int p = stack.back();
        stack.pop_back();
        const std::uint8_t m = level.mask[p];
        int pins = 0;
        for (const auto& [link, q] :
             {std::pair{kLeft, p - 1}, {kRight, p + 1}, {kUp, p - s}, {kDown, p + s}}) {
          if (!(m & link)) continue;
          // A link to a Dirichlet pixel does not join components (it is a constant there).
          if (level.mask[q] & kFixed) {
            ++pins;
            continue;
          }
          if (level.component[q] >= 0) continue;
          level.component[q] = label;
          stack.push_back(q);
        }
        if (pins) level.pinned.push_back({p, static_cast<float>(pins)});
      }
    }
  }
}

void prolongationTable(int fine, int coarse, std::vector<int>& near, std::vector<int>& neighbour) {
  near.resize(fine);
  neighbour.resize(fine);
  for (int i = 0; i < fine; ++i) {
    near[i] = std::min(i / 2, coarse - 1);
    neighbour[i] = std::clamp((i % 2) ? near[i] + 1 : near[i] - 1, 0, coarse - 1);
  }
}

void prolongationSources(Level& fine, const Level& coarse) {
  constexpr std::uint8_t kAllSources = kNear | 7;
  fine.solution_sources.resize(fine.size);
  fine.correction_sources.resize(fine.size);
  for (size_t p = 0; p < fine.size; ++p) {
    fine.solution_sources[p] = fine.mask[p] & kFixed ? kNoSources : kAllSources;
  }
  fine.correction_sources = fine.solution_sources;
  fine.pending.assign(fine.size, 0);
  std::vector<int>& irregular = fine.irregular;
  irregular.clear();
  const auto mark = [&](int x, int y) {
    if (x < 0 || y < 0 || x >= fine.width || y >= fine.height) return;
    std::uint8_t& flag = fine.pending[fine.index(x, y)];
    if (!flag) irregular.push_back(y * fine.width + x);
    flag = 1;
  };
  for (int y = 0; y < fine.height; ++y) {
    for (int x = 0; x < fine.width; ++x) {
      if (fine.mask[fine.index(x, y)] == kAllLinks) continue;
      mark(x, y);  // and the neighbours, which look at its links
      mark(x - 1, y);
      mark(x + 1, y);
      mark(x, y - 1);
      mark(x, y + 1);
    }
  }
  for (int cy = 0; cy < coarse.height; ++cy) {
    for (int cx = 0; cx < coarse.width; ++cx) {
      if (coarse.mask[coarse.index(cx, cy)] == kAllLinks) continue;
      // The fine pixels that take (cx, cy) as a source: fine columns 2cx - 1 .. 2cx + 2.
      for (int y = 2 * cy - 1; y <= 2 * cy + 2; ++y) {
        for (int x = 2 * cx - 1; x <= 2 * cx + 2; ++x) mark(x, y);
      }
    }
  }
  for (const int q : irregular) pixelSources(fine, coarse, q % fine.width, q / fine.width);
}

}  // namespace vicc_glyphs::multigrid_detail
