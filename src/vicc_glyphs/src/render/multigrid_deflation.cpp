#include "multigrid_deflation.hpp"

#include <algorithm>
#include <stdexcept>

namespace vicc_glyphs::multigrid_detail {

void DeflationSpace::build(const FineLevel& fine, const std::vector<int>& singletons) {
  count_ = 0;
  markInterior(fine, singletons);
  joinPieces(fine);
  compactLabels(fine);
  factorise(fine);
}

// Interior: linked to four free pixels, so not next to a curve, a Dirichlet pixel or the image
// border. A neck of one or two pixels between two regions has no interior pixel.
void DeflationSpace::markInterior(const FineLevel& fine, const std::vector<int>& singletons) {
  interior_.resize(fine.size);
  const std::uint8_t* __restrict mask = fine.mask.data();
  std::uint8_t* __restrict interior = interior_.data();
  const int s = fine.stride;
  // Every entry is written (the ghost border's 0) and the row loop has no branch, so that it
  // vectorises.
  std::fill_n(interior, fine.index(0, 0), std::uint8_t{0});
  for (int y = 0; y < fine.height; ++y) {
    const int begin = fine.index(0, y), end = fine.index(fine.width, y);
    for (int p = begin; p < end; ++p) {
      const std::uint8_t around = mask[p - 1] | mask[p + 1] | mask[p - s] | mask[p + s];
      interior[p] = (mask[p] == kAllLinks) & !(around & kFixed);  // kInterior or 0
    }
    interior[end] = interior[end + 1] = 0;  // right border, left border of the next row
  }
  std::fill(interior + fine.index(0, fine.height) - 1, interior + fine.size, std::uint8_t{0});
  for (const int p : singletons) interior[p] = kSingleton;
}

// Union-find within each kTileSize square: interior pixels join their interior neighbours
// (unless the link between them is a hole of one or two links in a wall of cut links); every
// other free pixel joins one linked interior neighbour (never two, so a neck does not merge the
// regions on its sides), or, without one, its linked neighbours of the same kind.
void DeflationSpace::joinPieces(const FineLevel& fine) {
  parent_.resize(fine.size);
  for (size_t p = 0; p < fine.size; ++p) parent_[p] = static_cast<int>(p);
  const std::uint8_t* mask = fine.mask.data();
  const std::uint8_t* interior = interior_.data();
  const int s = fine.stride;
  // Per column: whether the pixel there in the row above joined its left neighbour.
  left_joined_.assign(static_cast<size_t>(fine.width), 0);
  for (int y = 0; y < fine.height; ++y) {
    const bool up_inside = y % kTileSize != 0;
    bool left_joined_up = false;  // whether the left neighbour joined the pixel above it
    for (int x = 0; x < fine.width; ++x) {
      const int p = fine.index(x, y);
      bool joins_left = false, joins_up = false;
      if (interior[p] == kInterior) {
        // Not through a hole in a wall of cut links: the links beside this one must be there.
        // p is still its own root: hang it below its left neighbour's parent (short chains).
        joins_left = x % kTileSize != 0 && interior[p - 1] == kInterior &&
                     (mask[p - s] & mask[p + s] & kLeft);
        if (joins_left) parent_[p] = parent_[p - 1];
        joins_up = up_inside && interior[p - s] == kInterior && (mask[p - 1] & mask[p + 1] & kUp);
        // p and p - s are one set already when p joined its left neighbour, that one the pixel
        // above it, and that one p - s (most pixels of a large piece): no finds then.
        if (joins_up && !(joins_left && left_joined_up && left_joined_[x])) unite(p, p - s);
      }
      left_joined_[x] = joins_left;
      left_joined_up = joins_up;
    }
  }
  for (int y = 0; y < fine.height; ++y) {
    for (int x = 0; x < fine.width; ++x) {
      const int p = fine.index(x, y);
      const std::uint8_t m = mask[p];
      if ((m & kFixed) || interior[p]) continue;  // interior, or a singleton
      const bool inside[4] = {x % kTileSize != 0, (x + 1) % kTileSize != 0 && x + 1 < fine.width,
                              y % kTileSize != 0, (y + 1) % kTileSize != 0 && y + 1 < fine.height};
      const std::uint8_t links[4] = {kLeft, kRight, kUp, kDown};
      const int offsets[4] = {-1, 1, -s, s};
      bool joined = false;
      for (int k = 0; k < 4 && !joined; ++k) {
        if (inside[k] && (m & links[k]) && interior[p + offsets[k]] == kInterior) {
          parent_[p] = find(p + offsets[k]);
          joined = true;
        }
      }
      if (joined) continue;
      for (int k = 0; k < 4; k += 2) {  // left and up: the pixels before p
        const int q = p + offsets[k];
        if (inside[k] && (m & links[k]) && !(mask[q] & kFixed) && !interior[q] &&
            !hasInteriorLink(fine, q)) {
          unite(p, q);
        }
      }
    }
  }
}

// Whether the non-interior free pixel q joined an interior neighbour in its square.
bool DeflationSpace::hasInteriorLink(const FineLevel& fine, int q) const {
  const int x = q % fine.stride - 1, y = q / fine.stride - 1;
  const std::uint8_t m = fine.mask[q];
  const int s = fine.stride;
  return (x % kTileSize != 0 && (m & kLeft) && interior_[q - 1] == kInterior) ||
         ((x + 1) % kTileSize != 0 && (m & kRight) && interior_[q + 1] == kInterior) ||
         (y % kTileSize != 0 && (m & kUp) && interior_[q - s] == kInterior) ||
         ((y + 1) % kTileSize != 0 && (m & kDown) && interior_[q + s] == kInterior);
}

// Numbers the pieces 0..count_-1 in scan order of the first pixel met; count_ at everything
// that is not a free pixel.
void DeflationSpace::compactLabels(const FineLevel& fine) {
  constexpr std::uint32_t kUnset = ~std::uint32_t{0};
  labels_.assign(fine.size, kUnset);
  for (int y = 0; y < fine.height; ++y) {
    for (int p = fine.index(0, y), end = fine.index(fine.width, y); p < end; ++p) {
      if (!fine.isFree(p)) continue;
      // A root is only read through find(): its entry holds the number, a member's its own.
      const int root = find(p);
      if (labels_[root] == kUnset) labels_[root] = static_cast<std::uint32_t>(count_++);
      labels_[p] = labels_[root];
    }
  }
  for (std::uint32_t& label : labels_) {
    if (label == kUnset) label = static_cast<std::uint32_t>(count_);
  }
}

// E = Z^T A Z: per piece the links that leave it on the diagonal, minus the links between two
// pieces off it. Also collects the boundary pixels.
void DeflationSpace::factorise(const FineLevel& fine) {
  boundary_.clear();
  triplets_.clear();
  diagonal_.assign(static_cast<size_t>(count_), 0.0);
  const std::uint32_t none = static_cast<std::uint32_t>(count_);
  const int s = fine.stride;
  const std::uint32_t* labels = labels_.data();
  for (int y = 0; y < fine.height; ++y) {
    for (int p = fine.index(0, y), end = fine.index(fine.width, y); p < end; ++p) {
      const std::uint32_t k = labels[p];
      // The common case: all four neighbours in p's piece (or p not free). No branches, so
      // that this test vectorises.
      if ((labels[p - 1] == k) & (labels[p + 1] == k) & (labels[p - s] == k) &
          (labels[p + s] == k)) {
        continue;
      }
      if (k == none) continue;
      const std::uint8_t m = fine.mask[p];
      const std::uint32_t around[4] = {labels_[p - 1], labels_[p + 1], labels_[p - s],
                                       labels_[p + s]};
      const std::uint8_t links[4] = {kLeft, kRight, kUp, kDown};
      bool leaves = false;
      for (int j = 0; j < 4; ++j) {
        if (!(m & links[j]) || around[j] == k) continue;
        leaves = true;
        diagonal_[k] += 1.0;
        if (around[j] != none) triplets_.emplace_back(k, around[j], -1.0);
      }
      if (leaves) boundary_.push_back(p);
    }
  }
  for (int k = 0; k < count_; ++k) triplets_.emplace_back(k, k, diagonal_[k]);
  coarse_.resize(count_, count_);
  coarse_.setFromTriplets(triplets_.begin(), triplets_.end());
  factor_.compute(coarse_);
  if (factor_.info() != Eigen::Success) {
    throw std::runtime_error("multigrid: the deflation matrix is not positive definite");
  }
}

}  // namespace vicc_glyphs::multigrid_detail
