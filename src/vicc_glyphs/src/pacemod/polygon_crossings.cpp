#include "vicc_glyphs/pacemod/polygon_crossings.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace vicc_glyphs {
namespace pacemod {
namespace {

// The intersection of the lines through a0 a1 and b0 b1 (not parallel).
Point2 intersection(const Point2& a0, const Point2& a1, const Point2& b0, const Point2& b1) {
  const Point2 da = a1 - a0, db = b1 - b0;
  return a0 + (cross(b0 - a0, db) / cross(da, db)) * da;
}

bool properlyCross(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  return d1 * d2 < 0.0 && d3 * d4 < 0.0;
}

// Neighbouring segments of one polyline share a point; so do the first and last of a closed one.
bool adjacent(int segments, bool closed, int i, int j) {
  const int gap = std::abs(i - j);
  return gap <= 1 || (closed && gap == segments - 1);
}

// The next float towards -infinity (+infinity with `up`) of a finite float: one step of its
// bit pattern, inline (std::nextafter is a library call, four per box).
float nextFloat(float value, bool up) {
  const float smallest = std::numeric_limits<float>::denorm_min();
  if (value == 0.0f) return up ? smallest : -smallest;
  std::uint32_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  bits = (value > 0.0f) == up ? bits + 1 : bits - 1;
  std::memcpy(&value, &bits, sizeof bits);
  return value;
}

// `value` rounded to a float towards -infinity (below) or +infinity (above).
float below(double value) {
  const float rounded = static_cast<float>(value);
  return rounded > value && std::isfinite(rounded) ? nextFloat(rounded, false) : rounded;
}
float above(double value) {
  const float rounded = static_cast<float>(value);
  return rounded < value && std::isfinite(rounded) ? nextFloat(rounded, true) : rounded;
}

// A float box that contains the segment's double box: it only preselects pairs (the crossing
// test reads the double points; a box rounded to the nearest float could leave a cell that the
// crossing point lies in), and half the bytes of a double box keep the buckets of a
// high-frequency wave (tens of thousands of boxes) in the cache: `vicc_glyph modify` of the
// brain with rectangle waves 12/10 mm, 1.2 mm, spent a third less time in the search.
struct SegmentBox {
  // Without initialisers, so that resizing the buckets does not zero them first (they are
  // filled right after).
  SegmentBox() {}
  SegmentBox(SegmentRef segment, const Point2& lo, const Point2& hi)
      : lo_x(below(lo.x())),
        lo_y(below(lo.y())),
        hi_x(above(hi.x())),
        hi_y(above(hi.y())),
        line(segment.line),
        segment(segment.segment) {}
  SegmentRef ref() const { return {line, segment}; }
  float lo_x, lo_y, hi_x, hi_y;
  int line, segment;
};

// The cells a box touches: columns x0..x1, rows y0..y1.
struct CellRange {
  int x0, x1, y0, y1;
};

// Segments bucketed by the grid cells their bounding boxes touch (a counting sort: cell c
// holds bucketed[start[c]] ... bucketed[start[c + 1] - 1], the boxes in increasing lo.x, so
// that a sweep along x meets only the pairs whose x ranges overlap). Each finite segment's box
// and cell range are made once; the arrays are the caller's, kept between searches, since a
// high-frequency wave has tens of thousands of segments and fresh memory costs page faults.
struct SegmentGrid {
  static constexpr double kMaxCells = 1 << 22;
  std::vector<SegmentBox>& bucketed;
  std::vector<int>& start;
  Point2 origin = Point2::Zero();
  double cell = 1.0, inverse_cell = 1.0;
  long long nx = 0, ny = 0;

  // Coordinates are at or right of (below) the origin, the smallest box corner: truncation is
  // the floor. Clamped to the grid against round-off at the far end.
  static int index(double offset, double inverse_cell, long long count) {
    const long long i = offset > 0.0 ? static_cast<long long>(offset * inverse_cell) : 0;
    return static_cast<int>(i < count ? i : count - 1);
  }
  int column(double x) const { return index(x - origin.x(), inverse_cell, nx); }
  int row(double y) const { return index(y - origin.y(), inverse_cell, ny); }

  CellRange cellsOf(const SegmentBox& box) const {
    return {column(box.lo_x), column(box.hi_x), row(box.lo_y), row(box.hi_y)};
  }

  template <class Visit>
  void forEachCell(const CellRange& range, Visit&& visit) const {
    for (long long y = range.y0; y <= range.y1; ++y) {
      for (long long x = range.x0; x <= range.x1; ++x) visit(y * nx + x);
    }
  }

  // Every segment's box, skipping segments with a non-finite end.
  static void collectBoxes(const std::vector<Polyline>& lines, std::vector<SegmentBox>& boxes) {
    boxes.clear();
    for (int l = 0; l < static_cast<int>(lines.size()); ++l) {
      for (int i = 0; i + 1 < static_cast<int>(lines[l].size()); ++i) {
        const Point2 lo = lines[l][i].cwiseMin(lines[l][i + 1]);
        const Point2 hi = lines[l][i].cwiseMax(lines[l][i + 1]);
        // Beyond float range the box is infinite: the search fails below (too large).
        if (lo.allFinite() && hi.allFinite()) boxes.emplace_back(SegmentRef{l, i}, lo, hi);
      }
    }
  }

  SegmentGrid(const std::vector<Polyline>& lines, double min_cell, std::vector<SegmentBox>& boxes,
              std::vector<CellRange>& ranges, std::vector<SegmentBox>& bucketed_storage,
              std::vector<int>& start_storage)
      : bucketed(bucketed_storage), start(start_storage) {
    start.clear();
    if (!(min_cell > 0.0) || !std::isfinite(min_cell)) {
      throw std::invalid_argument("findCrossings: the cell size must be a finite number > 0");
    }
    collectBoxes(lines, boxes);
    if (boxes.empty()) return;
    Point2 lo = Point2::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (const SegmentBox& box : boxes) {
      lo = lo.cwiseMin(Point2(box.lo_x, box.lo_y));
      hi = hi.cwiseMax(Point2(box.hi_x, box.hi_y));
    }
    origin = lo;
    if (!(hi - lo).allFinite()) throw std::invalid_argument("findCrossings: coordinates too large");
    // A coarser grid finds the same crossings: only the number of pairs tried grows.
    cell = min_cell;
    const auto cells = [&](double size) {
      return (std::floor((hi.x() - lo.x()) / size) + 1.0) *
             (std::floor((hi.y() - lo.y()) / size) + 1.0);
    };
    while (!(cells(cell) <= kMaxCells)) cell *= 2.0;
    inverse_cell = 1.0 / cell;
    nx = static_cast<long long>(std::floor((hi.x() - lo.x()) / cell)) + 1;
    ny = static_cast<long long>(std::floor((hi.y() - lo.y()) / cell)) + 1;
    // Counts per cell, summed up to each cell's end; filling backwards leaves each its start.
    start.assign(static_cast<std::size_t>(nx * ny) + 1, 0);
    ranges.resize(boxes.size());
    for (std::size_t b = 0; b < boxes.size(); ++b) {
      ranges[b] = cellsOf(boxes[b]);
      forEachCell(ranges[b], [&](long long c) { ++start[c]; });
    }
    for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
    bucketed.resize(start.back());
    for (std::size_t b = 0; b < boxes.size(); ++b) {
      forEachCell(ranges[b], [&](long long c) { bucketed[--start[c]] = boxes[b]; });
    }
    for (std::size_t c = 0; c + 1 < start.size(); ++c) {
      if (start[c + 1] - start[c] < 2) continue;
      std::sort(bucketed.begin() + start[c], bucketed.begin() + start[c + 1],
                [](const SegmentBox& a, const SegmentBox& b) { return a.lo_x < b.lo_x; });
    }
  }
};

// A crossing pair shares every cell that both bounding boxes touch; it is reported only in
// the cell of its crossing point (clamped into both boxes against round-off), so exactly once.
bool ownedByCell(const SegmentGrid& grid, const Point2& a0, const Point2& a1, const Point2& b0,
                 const Point2& b1, long long cell) {
  const Point2 lo = a0.cwiseMin(a1).cwiseMax(b0.cwiseMin(b1));
  const Point2 hi = a0.cwiseMax(a1).cwiseMin(b0.cwiseMax(b1));
  const Point2 point = intersection(a0, a1, b0, b1).cwiseMax(lo).cwiseMin(hi);
  return grid.row(point.y()) * grid.nx + grid.column(point.x()) == cell;
}

}  // namespace

Point2 crossingPoint(const std::vector<Polyline>& lines, const Crossing& crossing) {
  const Polyline& a = lines[crossing.a.line];
  const Polyline& b = lines[crossing.b.line];
  return intersection(a[crossing.a.segment], a[crossing.a.segment + 1], b[crossing.b.segment],
                      b[crossing.b.segment + 1]);
}

struct CrossingFinder::Buckets {
  std::vector<SegmentBox> boxes;
  std::vector<CellRange> ranges;
  std::vector<SegmentBox> bucketed;
  std::vector<int> start;
};

CrossingFinder::CrossingFinder() : buckets_(std::make_unique<Buckets>()) {}
CrossingFinder::~CrossingFinder() = default;

std::vector<Crossing> findCrossings(const std::vector<Polyline>& lines, double cell) {
  return CrossingFinder().find(lines, cell);
}

std::vector<Crossing> CrossingFinder::find(const std::vector<Polyline>& lines, double cell) {
  std::vector<char> closed(lines.size());
  for (std::size_t l = 0; l < lines.size(); ++l) {
    closed[l] = lines[l].size() > 1 && (lines[l].front() - lines[l].back()).norm() < 1e-9;
  }
  const SegmentGrid grid(lines, cell, buckets_->boxes, buckets_->ranges, buckets_->bucketed,
                         buckets_->start);
  std::vector<Crossing> crossings;
  for (long long c = 0; c + 1 < static_cast<long long>(grid.start.size()); ++c) {
    for (int a = grid.start[c]; a < grid.start[c + 1]; ++a) {
      const SegmentBox& box_a = grid.bucketed[a];
      // Densely sampled curves put many short segments into a cell: most pairs are apart. The
      // later boxes start at or right of box_a's left edge; past its right edge none overlaps.
      for (int b = a + 1; b < grid.start[c + 1] && grid.bucketed[b].lo_x <= box_a.hi_x; ++b) {
        const SegmentBox& box_b = grid.bucketed[b];
        if (box_a.lo_y > box_b.hi_y || box_b.lo_y > box_a.hi_y) continue;
        // Canonical order, so that the crossing point is computed the same in every cell.
        SegmentRef p = box_a.ref(), q = box_b.ref();
        if (std::tie(q.line, q.segment) < std::tie(p.line, p.segment)) std::swap(p, q);
        const int segments = static_cast<int>(lines[p.line].size()) - 1;
        if (p.line == q.line && adjacent(segments, closed[p.line], p.segment, q.segment)) continue;
        const Point2& a0 = lines[p.line][p.segment];
        const Point2& a1 = lines[p.line][p.segment + 1];
        const Point2& b0 = lines[q.line][q.segment];
        const Point2& b1 = lines[q.line][q.segment + 1];
        if (!properlyCross(a0, a1, b0, b1)) continue;
        if (ownedByCell(grid, a0, a1, b0, b1, c)) crossings.push_back({p, q});
      }
    }
  }
  // A deterministic order that does not depend on the bucketing.
  std::sort(crossings.begin(), crossings.end(), [](const Crossing& x, const Crossing& y) {
    return std::tie(x.a.line, x.a.segment, x.b.line, x.b.segment) <
           std::tie(y.a.line, y.a.segment, y.b.line, y.b.segment);
  });
  return crossings;
}

}  // namespace pacemod
}  // namespace vicc_glyphs
