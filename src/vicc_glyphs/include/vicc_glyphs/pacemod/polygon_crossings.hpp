#pragma once
// Proper crossings between polyline segments (the polygon check for self-intersections of
// modified contours), found with a uniform grid of segment buckets.

#include <memory>
#include <vector>

#include "vicc_glyphs/pacemod/polyline.hpp"

namespace vicc_glyphs {
namespace pacemod {

struct SegmentRef {
  int line = 0;     ///< index into the polylines
  int segment = 0;  ///< segment i runs from point i to point i + 1
};

struct Crossing {
  SegmentRef a;
  SegmentRef b;
};

/// Every pair of segments that cross properly (touching end points and the neighbours within one
/// closed polyline do not count), within one polyline and between different ones, each once,
/// ordered by (a, b) with a < b. `cell` is the grid's smallest cell in the polylines' units; a
/// coarser one is used where a finer grid would exceed 4M cells (same result, more pairs tried).
/// The default suits PACEMOD's waves: the sweep along x in each cell keeps a full cell cheap, and
/// finer cells cost more in walking a 512 px glyph's mostly empty cells (2 px: 65,536 of them per
/// search) than they save in pairs (callgrind, bench README session 40).
/// Throws std::invalid_argument for a cell that is not > 0 or coordinates whose extent overflows.
std::vector<Crossing> findCrossings(const std::vector<Polyline>& lines, double cell = 8.0);

/// findCrossings with its buckets kept between calls: the polygon check searches the same
/// contours again in every repair round, and buckets of tens of thousands of segments (the brain
/// with rectangle waves at 12 waves/10 mm, 1.2 mm: 16,600 as drawn, 68,300 at 16 points per
/// span) in fresh memory cost a page fault per 4 KiB, as much as the search itself.
class CrossingFinder {
 public:
  CrossingFinder();
  ~CrossingFinder();
  CrossingFinder(const CrossingFinder&) = delete;
  CrossingFinder& operator=(const CrossingFinder&) = delete;

  /// As findCrossings(lines, cell).
  std::vector<Crossing> find(const std::vector<Polyline>& lines, double cell = 8.0);

 private:
  struct Buckets;
  std::unique_ptr<Buckets> buckets_;
};

/// Where the two segments of a crossing of `lines` (as found by findCrossings) meet.
Point2 crossingPoint(const std::vector<Polyline>& lines, const Crossing& crossing);

}  // namespace pacemod
}  // namespace vicc_glyphs
