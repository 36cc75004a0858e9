#pragma once
// Proper crossings between polyline segments (the polygon check for self-intersections of
// modified contours), found by pairing runs of segments along which x does not turn back (two
// segments of one such run cross only if they are neighbours) through a uniform grid of their
// boxes, and merging each pair's segments in the order of x.

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
/// ordered by (a, b) with a < b. `cell` is the grid's smallest cell in the polylines' units (a
/// coarser one is used where a finer grid would exceed 4M cells) and the largest width or height
/// of a run's box: the same result for any cell, only the work differs. The default suits
/// PACEMOD's waves (callgrind, bench README sessions 40 and 41: 2-16 px tried).
/// Throws std::invalid_argument for a cell that is not > 0 or coordinates whose extent overflows.
std::vector<Crossing> findCrossings(const std::vector<Polyline>& lines, double cell = 8.0);

/// findCrossings with its buckets kept between calls: the polygon check searches the same
/// contours again in every repair round, and fresh memory costs a page fault per 4 KiB.
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
