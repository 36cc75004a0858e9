#include "vicc_glyphs/render/constant_regions.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace vicc_glyphs {
namespace {

// Eight bytes at `p` as one word (a run of pixels' flags or ids).
std::uint64_t word(const std::uint8_t* p) {
  std::uint64_t value;
  std::memcpy(&value, p, sizeof value);
  return value;
}

// Whether a link leaves the grid (the assembler never makes one; a hand-made problem might,
// and the passes below read links without coordinates).
bool linksLeaveGrid(const GridProblem& problem) {
  const int w = problem.width, h = problem.height;
  for (int y = 0; y < h; ++y) {
    if (problem.couples_right[y * w + w - 1]) return true;
  }
  for (int x = 0; x < w; ++x) {
    if (problem.couples_down[(h - 1) * w + x]) return true;
  }
  return false;
}

}  // namespace

bool ConstantRegions::solve(const GridProblem& problem, float spread, float* values) {
  if (linksLeaveGrid(problem) || !identifyColors(problem, spread)) return false;
  if (!propagate(problem)) return false;
  const int n = problem.pixelCount(), channels = problem.channels;
  const std::uint8_t* fixed = problem.fixed.data();
  std::copy(problem.values.begin(), problem.values.end(), values);
  const std::uint8_t* id = ids_.data();
  if (channels == 3) {
    float* to = values;
    for (int p = 0; p < n; ++p, to += 3) {
      if (fixed[p]) continue;
      const Color3& color = colors_[id[p] - 1];
      to[0] = color[0], to[1] = color[1], to[2] = color[2];
    }
  } else {
    for (int p = 0; p < n; ++p) {
      if (!fixed[p]) values[p] = colors_[id[p] - 1][0];
    }
  }
  return true;
}

// Colour ids 1.. for the Dirichlet pixels: a value within half the spread (per channel) of a
// colour already met gets its id, so that all values of one id lie within the spread.
bool ConstantRegions::identifyColors(const GridProblem& problem, float spread) {
  const int n = problem.pixelCount(), channels = problem.channels;
  const float half = 0.5f * spread;
  ids_.assign(static_cast<size_t>(n), 0);
  colors_.clear();
  std::size_t last = 0;  // the id met last: neighbouring Dirichlet pixels mostly share it
  for (int p = 0; p < n; ++p) {
    if (p + 8 <= n && word(problem.fixed.data() + p) == 0) {  // eight free pixels
      p += 7;
      continue;
    }
    if (!problem.fixed[p]) continue;
    const float* v = problem.values.data() + static_cast<size_t>(p) * channels;
    const auto near = [&](const Color3& color) {
      for (int c = 0; c < channels; ++c) {
        if (!(std::abs(v[c] - color[c]) <= half)) return false;
      }
      return true;
    };
    if (last >= colors_.size() || !near(colors_[last])) {
      last = 0;
      while (last < colors_.size() && !near(colors_[last])) ++last;
      if (last == colors_.size()) {
        // Colours that diffuse (gradients) have many values: no constant regions to find.
        if (colors_.size() == kMaxColors) return false;
        Color3 color{};
        std::copy_n(v, channels, color.begin());
        colors_.push_back(color);
      }
    }
    ids_[p] = static_cast<std::uint8_t>(last + 1);
  }
  return true;
}

namespace {

constexpr std::uint64_t kOnes = 0x0101010101010101ULL;  // a flag set in all eight bytes

// Whether ids a and b are both set and differ.
inline unsigned differ(unsigned a, unsigned b) { return (a != b) & (a * b != 0); }

}  // namespace

// Carries the Dirichlet pixels' ids over the links into the free pixels: a forward raster pass
// (from the left and upper neighbour) and a backward one (right and lower), failing where two
// ids meet. An id once set stays, so the two passes see every link at a free pixel with the
// ids at both ends final (a link from a free pixel to a later one in the backward pass's
// order: when the earlier one is reached). Within a region's inside, eight free pixels linked
// all round whose neighbours carry the id already met are taken at once. Per pixel
// branch-free (links and flags are 0 or 1, ids 1..kMaxColors): a conflict is caught at the
// row's end.
bool ConstantRegions::propagate(const GridProblem& problem) {
  const int w = problem.width, h = problem.height;
  const std::uint8_t* fixed = problem.fixed.data();
  const std::uint8_t* right = problem.couples_right.data();
  const std::uint8_t* down = problem.couples_down.data();
  std::uint8_t* id = ids_.data();
  for (int y = 0; y < h; ++y) {
    unsigned conflict = 0;
    const int first = y * w, end = first + w;
    for (int p = first; p < end;) {
      if (p > first && y > 0 && p + 8 <= end) {
        const std::uint64_t same = kOnes * id[p - 1];
        if (word(fixed + p) == 0 && word(right + p - 1) == kOnes && word(down + p - w) == kOnes &&
            word(id + p - w) == same) {
          std::memcpy(id + p, &same, sizeof same);
          p += 8;
          continue;
        }
      }
      const unsigned left = p > first ? id[p - 1] * right[p - 1] : 0u;
      const unsigned up = y > 0 ? id[p - w] * down[p - w] : 0u;
      conflict |= (fixed[p] ^ 1u) & differ(left, up);
      id[p] = fixed[p] ? id[p] : static_cast<std::uint8_t>(left | up);
      ++p;
    }
    if (conflict) return false;
  }
  unsigned unknown = 0;
  for (int y = h - 1; y >= 0; --y) {
    unsigned conflict = 0;
    const int first = y * w, last = first + w - 1;
    for (int p = last; p >= first;) {
      if (p < last && y + 1 < h && p - 7 >= first && id[p + 1]) {
        const std::uint64_t same = kOnes * id[p + 1];
        const std::uint64_t own = word(id + p - 7);
        if (word(fixed + p - 7) == 0 && word(right + p - 7) == kOnes &&
            word(down + p - 7) == kOnes && (own == same || own == 0) &&
            word(id + p + w - 7) == same) {
          std::memcpy(id + p - 7, &same, sizeof same);
          p -= 8;
          continue;
        }
      }
      const unsigned own = id[p], next = p < last ? id[p + 1] * right[p] : 0u;
      const unsigned below = y + 1 < h ? id[p + w] * down[p] : 0u;
      const unsigned free = fixed[p] ^ 1u;
      conflict |= free & (differ(own, next) | differ(own, below) | differ(next, below));
      id[p] = free ? static_cast<std::uint8_t>(own | next | below) : id[p];
      unknown |= free & (id[p] == 0);
      --p;
    }
    if (conflict) return false;
  }
  return !unknown || fillRemaining(problem);
}

// The free pixels the raster passes left without an id (behind turns of a region): a search
// over the links from those that have one, then a check of every link. False when some
// remain (a region without a Dirichlet pixel, whose problem is singular) or two ids meet.
bool ConstantRegions::fillRemaining(const GridProblem& problem) {
  const int w = problem.width, n = problem.pixelCount();
  std::uint8_t* id = ids_.data();
  spreadLabelsOverLinks(problem, id, queue_);  // a conflicting neighbour shows in the check below
  for (int p = 0; p < n; ++p) {
    if (!id[p]) return false;
  }
  // The search set ids without comparing them: every link at a free pixel must join equal ones.
  const std::uint8_t* fixed = problem.fixed.data();
  for (int p = 0; p < n; ++p) {
    const bool free_link_right = problem.couples_right[p] && !(fixed[p] && fixed[p + 1]);
    const bool free_link_down = problem.couples_down[p] && !(fixed[p] && fixed[p + w]);
    if ((free_link_right && id[p] != id[p + 1]) || (free_link_down && id[p] != id[p + w])) {
      return false;
    }
  }
  return true;
}

}  // namespace vicc_glyphs
