#pragma once
// Proper crossings between polyline segments (the polygon check for self-intersections of
// modified contours), found with a uniform grid of segment buckets.

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
/// Throws std::invalid_argument for a cell that is not > 0 or coordinates whose extent overflows.
std::vector<Crossing> findCrossings(const std::vector<Polyline>& lines, double cell = 8.0);

/// Where the two segments of a crossing of `lines` (as found by findCrossings) meet.
Point2 crossingPoint(const std::vector<Polyline>& lines, const Crossing& crossing);

}  // namespace pacemod
}  // namespace vicc_glyphs
