#pragma once
// Local relaxation of the finest level's start (internal to the renderer; see
// docs/rendering.md). FMG's start q + P u_1 is poor at a few spots that P cannot represent:
// a free pixel in the wedge at a sharp wave tip or next to a curve's end, with errors of 0.1-0.2
// there while the rest of the image is within 1e-3. The V-cycle reduces such a spot only about
// tenfold per CG iteration, so it alone cost waved glyphs a second iteration. A few Gauss-Seidel
// sweeps on the pixels around the spots (Brandt's local relaxation near singularities) remove
// it at the cost of a few thousand pixel updates; the smooth remainder is the coarse levels'.

#include <cstdint>
#include <vector>

#include "multigrid_levels.hpp"

namespace vicc_glyphs::multigrid_detail {

class LocalRelaxationSet {
 public:
  /// Squares of `radius` around the `seeds` (fine indices of free pixels whose residual is
  /// large); reuses the memory of the last build. Seeds must be in index order.
  void build(const FineLevel& fine, const std::vector<int>& seeds, int radius);

  /// The free pixels of the squares, in index order (the forward sweep's order).
  const std::vector<int>& pixels() const { return pixels_; }
  /// The pixels whose residual a sweep changes: pixels() and their four neighbours (free or
  /// not), in index order.
  const std::vector<int>& affected() const { return affected_; }

 private:
  // Per fine index: kInner inside a square, kRing one pixel beyond it; all 0 between builds.
  std::vector<std::uint8_t> marks_;
  std::vector<int> pixels_, affected_;
};

}  // namespace vicc_glyphs::multigrid_detail
