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

// A float box that contains a chain's double box (see Chain): it only preselects pairs (the
// crossing test reads the double points; a box rounded to the nearest float could leave a cell
// that the crossing point lies in), and half the bytes of a double box keep the buckets in the
// cache.
struct ItemBox {
  // Without initialisers, so that resizing the buckets does not zero them first (they are
  // filled right after).
  ItemBox() {}
  ItemBox(int item, const Point2& lo, const Point2& hi)
      : lo_x(below(lo.x())),
        lo_y(below(lo.y())),
        hi_x(above(hi.x())),
        hi_y(above(hi.y())),
        item(item) {}
  float lo_x, lo_y, hi_x, hi_y;
  int item;
};

// The cells a box touches: columns x0..x1, rows y0..y1.
struct CellRange {
  int x0, x1, y0, y1;
};

// A run of consecutive segments of one polyline along which x never turns back (it stays or
// grows, or it stays or falls). Two segments of one chain that are not neighbours never cross
// properly: their x ranges meet at most in one value, which is an end of one of them or the x
// of a vertical line both lie on. So the search pairs chains, and walks two chains' segments in
// the order of x (a merge), instead of bucketing every segment: a 512 px wave has tens of
// thousands of segments but a few thousand chains.
struct Chain {
  int line = 0;
  int first = 0;         ///< its first segment
  int last = 0;          ///< its last segment (inclusive)
  bool falling = false;  ///< x falls along it: walked from `last` back to `first`
};

// -1, 0 or +1: whether x falls, stays or grows from a to b.
int xStep(const Point2& a, const Point2& b) { return (b.x() > a.x()) - (b.x() < a.x()); }

// The chains of every polyline with their boxes; segments with a non-finite end belong to none.
void collectChains(const std::vector<Polyline>& lines, double extent, std::vector<Chain>& chains,
                   std::vector<ItemBox>& boxes) {
  chains.clear();
  boxes.clear();
  for (int l = 0; l < static_cast<int>(lines.size()); ++l) {
    const Polyline& line = lines[l];
    const int points = static_cast<int>(line.size());
    for (int i = 0; i + 1 < points;) {
      if (!line[i].allFinite() || !line[i + 1].allFinite()) {
        ++i;
        continue;
      }
      Point2 lo = line[i].cwiseMin(line[i + 1]), hi = line[i].cwiseMax(line[i + 1]);
      int direction = xStep(line[i], line[i + 1]);
      int j = i + 1;  // the next segment, from line[j] to line[j + 1]
      for (; j + 1 < points && line[j + 1].allFinite(); ++j) {
        const int step = xStep(line[j], line[j + 1]);
        if (step != 0 && direction != 0 && step != direction) break;
        const Point2 grown_lo = lo.cwiseMin(line[j + 1]), grown_hi = hi.cwiseMax(line[j + 1]);
        if ((grown_hi - grown_lo).maxCoeff() > extent) break;
        if (step != 0) direction = step;
        lo = grown_lo;
        hi = grown_hi;
      }
      boxes.emplace_back(static_cast<int>(chains.size()), lo, hi);
      chains.push_back({l, i, j - 1, direction < 0});
      i = j;
    }
  }
}

// Boxes bucketed by the grid cells they touch (a counting sort: cell c holds bucketed[start[c]]
// ... bucketed[start[c + 1] - 1], the boxes in increasing lo.x, so that a sweep along x meets
// only the pairs whose x ranges overlap). The arrays are the caller's, kept between searches:
// fresh memory costs page faults.
struct BoxGrid {
  static constexpr double kMaxCells = 1 << 22;
  std::vector<ItemBox>& bucketed;
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
  long long cellOf(double x, double y) const { return row(y) * nx + column(x); }

  CellRange cellsOf(const ItemBox& box) const {
    return {column(box.lo_x), column(box.hi_x), row(box.lo_y), row(box.hi_y)};
  }

  template <class Visit>
  void forEachCell(const CellRange& range, Visit&& visit) const {
    for (long long y = range.y0; y <= range.y1; ++y) {
      for (long long x = range.x0; x <= range.x1; ++x) visit(y * nx + x);
    }
  }

  BoxGrid(const std::vector<ItemBox>& boxes, double min_cell, std::vector<CellRange>& ranges,
          std::vector<ItemBox>& bucketed_storage, std::vector<int>& start_storage)
      : bucketed(bucketed_storage), start(start_storage) {
    start.clear();
    if (boxes.empty()) return;
    Point2 lo = Point2::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (const ItemBox& box : boxes) {
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
                [](const ItemBox& a, const ItemBox& b) { return a.lo_x < b.lo_x; });
    }
  }
};

// The proper crossings between the segments of chains a and b (different chains; `box_b`
// contains b), appended to `crossings` with the lower (line, segment) first. Both chains'
// segments are taken in the order of x, so that their x ranges start and end in order: a merge
// visits every pair whose x ranges overlap.
class ChainPairWalk {
 public:
  ChainPairWalk(const std::vector<Polyline>& lines, const std::vector<char>& closed)
      : lines_(lines), closed_(closed) {}

  void operator()(const Chain& a, const Chain& b, const ItemBox& box_b,
                  std::vector<Crossing>& crossings) const {
    const InXOrder along_a(a), along_b(b);
    const Point2* pa = lines_[a.line].data();
    const Point2* pb = lines_[b.line].data();
    int from = 0;  // b's first segment (in x order) that can still meet a's current one
    for (int i = 0; i < along_a.count; ++i) {
      const int sa = along_a.segment(i);
      const Point2 &a0 = pa[sa], &a1 = pa[sa + 1];
      const double a_lo = std::min(a0.x(), a1.x()), a_hi = std::max(a0.x(), a1.x());
      if (a_lo > box_b.hi_x) break;  // so are a's later segments
      const double a_bottom = std::min(a0.y(), a1.y()), a_top = std::max(a0.y(), a1.y());
      if (a_hi < box_b.lo_x || a_top < box_b.lo_y || a_bottom > box_b.hi_y) continue;
      while (from < along_b.count && xHigh(pb, along_b.segment(from)) < a_lo) ++from;
      for (int k = from; k < along_b.count; ++k) {
        const int sb = along_b.segment(k);
        const Point2 &b0 = pb[sb], &b1 = pb[sb + 1];
        if (std::min(b0.x(), b1.x()) > a_hi) break;
        if (a_top < std::min(b0.y(), b1.y()) || std::max(b0.y(), b1.y()) < a_bottom) continue;
        SegmentRef p{a.line, sa}, q{b.line, sb};
        if (std::tie(q.line, q.segment) < std::tie(p.line, p.segment)) std::swap(p, q);
        const int segments = static_cast<int>(lines_[p.line].size()) - 1;
        if (p.line == q.line && adjacent(segments, closed_[p.line], p.segment, q.segment)) continue;
        if (properlyCross(a0, a1, b0, b1)) crossings.push_back({p, q});
      }
    }
  }

 private:
  // A chain's segments by increasing x: the k-th is begin + step * k.
  struct InXOrder {
    explicit InXOrder(const Chain& chain)
        : begin(chain.falling ? chain.last : chain.first),
          step(chain.falling ? -1 : 1),
          count(chain.last - chain.first + 1) {}
    int segment(int k) const { return begin + step * k; }
    int begin, step, count;
  };
  static double xHigh(const Point2* points, int segment) {
    return std::max(points[segment].x(), points[segment + 1].x());
  }

  const std::vector<Polyline>& lines_;
  const std::vector<char>& closed_;
};

}  // namespace

Point2 crossingPoint(const std::vector<Polyline>& lines, const Crossing& crossing) {
  const Polyline& a = lines[crossing.a.line];
  const Polyline& b = lines[crossing.b.line];
  return intersection(a[crossing.a.segment], a[crossing.a.segment + 1], b[crossing.b.segment],
                      b[crossing.b.segment + 1]);
}

struct CrossingFinder::Buckets {
  std::vector<Chain> chains;
  std::vector<ItemBox> boxes;
  std::vector<CellRange> ranges;
  std::vector<ItemBox> bucketed;
  std::vector<int> start;
};

CrossingFinder::CrossingFinder() : buckets_(std::make_unique<Buckets>()) {}
CrossingFinder::~CrossingFinder() = default;

std::vector<Crossing> findCrossings(const std::vector<Polyline>& lines, double cell) {
  return CrossingFinder().find(lines, cell);
}

std::vector<Crossing> CrossingFinder::find(const std::vector<Polyline>& lines, double cell) {
  if (!(cell > 0.0) || !std::isfinite(cell)) {
    throw std::invalid_argument("findCrossings: the cell size must be a finite number > 0");
  }
  std::vector<char> closed(lines.size());
  for (std::size_t l = 0; l < lines.size(); ++l) {
    closed[l] = lines[l].size() > 1 && (lines[l].front() - lines[l].back()).norm() < 1e-9;
  }
  Buckets& b = *buckets_;
  collectChains(lines, cell, b.chains, b.boxes);
  const BoxGrid grid(b.boxes, cell, b.ranges, b.bucketed, b.start);
  const ChainPairWalk walk(lines, closed);
  std::vector<Crossing> crossings;
  for (long long c = 0; c + 1 < static_cast<long long>(grid.start.size()); ++c) {
    for (int i = grid.start[c]; i < grid.start[c + 1]; ++i) {
      const ItemBox& box_a = grid.bucketed[i];
      // The later boxes start at or right of box_a's left edge; past its right edge none
      // overlaps.
      for (int j = i + 1; j < grid.start[c + 1] && grid.bucketed[j].lo_x <= box_a.hi_x; ++j) {
        const ItemBox& box_b = grid.bucketed[j];
        if (box_a.lo_y > box_b.hi_y || box_b.lo_y > box_a.hi_y) continue;
        // A pair of boxes shares every cell both touch; it is walked only in the cell of the
        // lower corner of their overlap (inside both), so exactly once.
        if (grid.cellOf(std::max(box_a.lo_x, box_b.lo_x), std::max(box_a.lo_y, box_b.lo_y)) != c) {
          continue;
        }
        walk(b.chains[box_a.item], b.chains[box_b.item], box_b, crossings);
      }
    }
  }
  // A deterministic order that does not depend on the chains or the bucketing.
  std::sort(crossings.begin(), crossings.end(), [](const Crossing& x, const Crossing& y) {
    return std::tie(x.a.line, x.a.segment, x.b.line, x.b.segment) <
           std::tie(y.a.line, y.a.segment, y.b.line, y.b.segment);
  });
  return crossings;
}

}  // namespace pacemod
}  // namespace vicc_glyphs
