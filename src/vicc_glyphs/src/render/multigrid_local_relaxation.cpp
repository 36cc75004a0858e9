#include "multigrid_local_relaxation.hpp"

#include <algorithm>

namespace vicc_glyphs::multigrid_detail {
namespace {

constexpr std::uint8_t kRing = 1, kInner = 2;

}  // namespace

void LocalRelaxationSet::build(const FineLevel& fine, const std::vector<int>& seeds, int radius) {
  marks_.resize(fine.size, 0);
  pixels_.clear();
  affected_.clear();
  // Squares of radius + 1 (clipped to the grid): their border ring holds the neighbours of the
  // inner square's pixels.
  const int outer = radius + 1;
  for (const int seed : seeds) {
    const int y = seed / fine.stride - 1, x = seed % fine.stride - 1;
    const int y0 = std::max(0, y - outer), y1 = std::min(fine.height - 1, y + outer);
    const int x0 = std::max(0, x - outer), x1 = std::min(fine.width - 1, x + outer);
    for (int yy = y0; yy <= y1; ++yy) {
      const bool inner_row = yy >= y - radius && yy <= y + radius;
      for (int xx = x0; xx <= x1; ++xx) {
        const int p = fine.index(xx, yy);
        const bool inner = inner_row && xx >= x - radius && xx <= x + radius;
        std::uint8_t& mark = marks_[static_cast<size_t>(p)];
        if (!mark) affected_.push_back(p);
        mark |= inner ? kInner : kRing;
      }
    }
  }
  std::sort(affected_.begin(), affected_.end());
  for (const int p : affected_) {
    if ((marks_[static_cast<size_t>(p)] & kInner) && fine.isFree(p)) pixels_.push_back(p);
    marks_[static_cast<size_t>(p)] = 0;
  }
}

}  // namespace vicc_glyphs::multigrid_detail
