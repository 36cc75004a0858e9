#include "vicc_glyphs/render/lattice_crossings.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "vicc_glyphs/dci/flattening.hpp"

namespace vicc_glyphs {
namespace {

struct CurveSample {
  Point2 point;
  double position;
};

// Collects the crossings piece by piece and hands each piece's on to `visit` one piece later,
// in their order, so that a touch can be taken out: where a curve comes to a line of pixel
// centres exactly at a piece end and turns back from it, the half-open ranges below count the
// line twice (at the end of the one piece and the start of the next), on the same link and in
// opposite directions. The curve touches that link and does not cross it; the pair would cut
// the link and give each of its pixels both sides' colours at the same distance, whose mean
// (grey) then spreads a halo into the region beside it.
class CrossingCollector {
 public:
  CrossingCollector(int curve, int width, int height,
                    const std::function<void(const LatticeCrossing&)>& visit)
      : curve_(curve), width_(width), height_(height), visit_(visit) {}

  // The crossings of the straight piece a -> b with the lines through pixel centres.
  void addPiece(const CurveSample& a, const CurveSample& b) {
    current_.clear();
    collect(a, b);
    cancelTouches();
    flush();
    held_.swap(current_);
  }

  // Hands on the crossings held back: at the end of a chain of pieces.
  void flush() {
    for (const Held& held : held_) {
      if (!held.touch) visit_(held.crossing);
    }
    held_.clear();
  }

 private:
  struct Held {
    LatticeCrossing crossing;
    double t = 0.0;  ///< where on its piece: 0 at the start, 1 at the end
    bool touch = false;
  };

  // The crossings of the straight piece a -> b with the lines through pixel centres, into
  // current_.
  void collect(const CurveSample& a, const CurveSample& b) {
    const Point2 d = b.point - a.point;
    const double length = d.norm();
    if (!(length > 1e-12)) return;
    const Point2 normal(d.y() / length, -d.x() / length);  // left normal, y-down frame
    const double footprint = 0.5 * (std::abs(normal.x()) + std::abs(normal.y()));
    // Rows: the line y = j + 0.5 carries the links (i, j) - (i + 1, j). Half-open ranges make
    // a curve passing through a piece end count once.
    const auto [row_begin, row_end] = lineRange(a.point.y(), b.point.y(), height_);
    // A slanted piece through a pixel centre crosses a row and a column line there; it is taken
    // to pass beside the centre as if the lattice were moved by (e, e^2), e -> 0 (below).
    const bool slanted = d.x() != 0.0 && d.y() != 0.0;
    for (int j = row_begin; j < row_end; ++j) {
      const double t = (j + 0.5 - a.point.y()) / d.y();
      const double x = a.point.x() + t * d.x();
      int i = static_cast<int>(std::floor(x - 0.5));
      if (slanted && onLatticePoint(x)) i = static_cast<int>(std::lround(x - 0.5)) - 1;
      report(a, b, t, {i, j}, {i + 1, j}, normal, footprint);
    }
    // Columns: the line x = i + 0.5 carries the links (i, j) - (i, j + 1).
    const auto [column_begin, column_end] = lineRange(a.point.x(), b.point.x(), width_);
    for (int i = column_begin; i < column_end; ++i) {
      const double t = (i + 0.5 - a.point.x()) / d.x();
      const double y = a.point.y() + t * d.y();
      int j = static_cast<int>(std::floor(y - 0.5));
      if (slanted && onLatticePoint(y)) {
        j = static_cast<int>(std::lround(y - 0.5)) - (d.x() * d.y() > 0.0 ? 0 : 1);
      }
      report(a, b, t, {i, j}, {i, j + 1}, normal, footprint);
    }
  }

  // Whether a crossing's other coordinate lies on a line of pixel centres, so that it is a
  // pixel centre. Both lines' crossings there named their links by std::floor, which put the
  // centre on the curve's left side for one and on its right for the other: the pixel then
  // took the mean of both colours, a grey whose halo spread into the flat region beside it.
  // Moved by (e, e^2), the centre lies on one side: the row line's crossing falls just before
  // it in x (the link to its left), the column line's just after it in y where the piece runs
  // down to the right or up to the left (dx dy > 0, the link below), else just before it.
  static bool onLatticePoint(double coordinate) {
    const double offset = coordinate - 0.5;
    return std::abs(offset - std::round(offset)) < kLatticePointTolerance;
  }
  static constexpr double kLatticePointTolerance = 1e-9;  // px; sample points snap to 1/1024

  // A crossing at the start of this piece and one at the end of the previous piece on the same
  // link, with the sides swapped: the curve touched the link at their shared point.
  void cancelTouches() {
    for (Held& start : current_) {
      if (start.t != 0.0) continue;
      for (Held& end : held_) {
        if (end.touch || end.t != 1.0) continue;
        const LatticeCrossing &x = start.crossing, &y = end.crossing;
        if (samePixel(x.left_pixel, y.right_pixel) && samePixel(x.right_pixel, y.left_pixel)) {
          start.touch = end.touch = true;
          break;
        }
      }
    }
  }

  static bool samePixel(const GridPixel& p, const GridPixel& q) { return p.x == q.x && p.y == q.y; }

  // Indices k in [0, count) with min(u, v) <= k + 0.5 < max(u, v).
  static std::pair<int, int> lineRange(double u, double v, int count) {
    const double low = std::min(u, v) - 0.5;
    const double high = std::max(u, v) - 0.5;
    const double begin = std::clamp(std::ceil(low), 0.0, static_cast<double>(count));
    const double end = std::clamp(std::ceil(high), 0.0, static_cast<double>(count));
    return {static_cast<int>(begin), static_cast<int>(end)};
  }

  bool inside(const GridPixel& p) const {
    return p.x >= 0 && p.y >= 0 && p.x < width_ && p.y < height_;
  }

  void report(const CurveSample& a, const CurveSample& b, double t, GridPixel first,
              GridPixel second, const Point2& normal, double footprint) {
    if (!inside(first) && !inside(second)) return;
    const Point2 at = a.point + t * (b.point - a.point);
    const double first_side = (Point2(first.x + 0.5, first.y + 0.5) - at).dot(normal);
    const double second_side = (Point2(second.x + 0.5, second.y + 0.5) - at).dot(normal);
    LatticeCrossing crossing;
    crossing.curve = curve_;
    crossing.position = a.position + t * (b.position - a.position);
    crossing.footprint = footprint;
    const bool first_is_left = first_side > second_side;
    crossing.left_pixel = first_is_left ? first : second;
    crossing.right_pixel = first_is_left ? second : first;
    crossing.left_distance = std::abs(first_is_left ? first_side : second_side);
    crossing.right_distance = std::abs(first_is_left ? second_side : first_side);
    const double first_link = (Point2(first.x + 0.5, first.y + 0.5) - at).norm();
    crossing.left_link_distance = first_is_left ? first_link : 1.0 - first_link;
    crossing.right_link_distance = 1.0 - crossing.left_link_distance;
    current_.push_back({crossing, t, false});
  }

  int curve_;
  int width_;
  int height_;
  const std::function<void(const LatticeCrossing&)>& visit_;
  std::vector<Held> held_;     ///< the previous piece's crossings, not yet handed on
  std::vector<Held> current_;  ///< this piece's
};

bool outsideGrid(const Point2* b, int width, int height) {
  double min_x = b[0].x(), max_x = b[0].x(), min_y = b[0].y(), max_y = b[0].y();
  for (int k = 1; k < 4; ++k) {
    min_x = std::min(min_x, b[k].x());
    max_x = std::max(max_x, b[k].x());
    min_y = std::min(min_y, b[k].y());
    max_y = std::max(max_y, b[k].y());
  }
  // The convex hull of the control points contains the segment; one pixel of margin keeps
  // the links of border pixels whose partner lies just outside.
  return max_x < -1.0 || max_y < -1.0 || min_x > width + 1.0 || min_y > height + 1.0;
}

// Sample points are snapped to 1/1024 grid pixel: a curve meant to run exactly along a line of
// pixel centres (common for axis-aligned icon edges) otherwise wobbles across it by rounding
// errors and cuts links on both sides at random.
Point2 snapped(const Point2& p) {
  constexpr double kSnap = 1024.0;
  return Point2(std::round(p.x() * kSnap) / kSnap, std::round(p.y() * kSnap) / kSnap);
}

// A curve that ends outside the image is meant to leave it. On a coarse grid the last pixel
// row or column reaches further past the image border than on the fine grid, so such an end
// could stop short of the last line of pixel centres and let the two sides mix around it;
// extending it straight on by a few grid pixels keeps the levels' geometry alike.
void extendEndsLeavingTheImage(const DiffusionCurve& curve, const DiffusionCurveImage& image,
                               double scale, CrossingCollector& collector) {
  const int segments = curve.segmentCount();
  constexpr double kExtension = 2.0;  // grid pixels
  const auto outside = [&](const Point2& p) {
    return p.x() < 0.0 || p.y() < 0.0 || p.x() > image.width || p.y() > image.height;
  };
  for (const bool at_start : {true, false}) {
    const double s = at_start ? 0.0 : segments;
    const Point2 end = curve.pointAt(s);
    if (!end.allFinite() || !outside(end)) continue;
    Point2 direction = curve.derivativeAt(s) * (at_start ? -1.0 : 1.0);
    if (!(direction.norm() > 1e-12)) {
      direction = at_start ? curve.control_points.front() - curve.control_points.back()
                           : curve.control_points.back() - curve.control_points.front();
    }
    if (!(direction.norm() > 1e-12) || !direction.allFinite()) continue;
    const CurveSample from{snapped(scale * end), s};
    const CurveSample to{scale * end + kExtension * direction.normalized(), s};
    if (at_start) {
      collector.addPiece(to, from);
    } else {
      collector.addPiece(from, to);
    }
    collector.flush();  // a piece on its own
  }
}

}  // namespace

void forEachLatticeCrossing(const DiffusionCurveImage& image, double scale, int width, int height,
                            const std::function<void(const LatticeCrossing&)>& visit) {
  for (size_t c = 0; c < image.curves.size(); ++c) {
    const DiffusionCurve& curve = image.curves[c];
    const int segments = curve.segmentCount();
    CrossingCollector collector(static_cast<int>(c), width, height, visit);
    const std::vector<char> beside_fold = segmentsBesideFolds(curve.control_points);
    for (int k = 0; k < segments; ++k) {
      Point2 b[4];
      for (int m = 0; m < 4; ++m) b[m] = scale * curve.control_points[3 * k + m];
      if (!b[0].allFinite() || !b[1].allFinite() || !b[2].allFinite() || !b[3].allFinite() ||
          outsideGrid(b, width, height)) {
        collector.flush();  // the chain of pieces breaks here
        continue;
      }
      // As PACEMOD's polygon checks (flattening.hpp).
      const int pieces = flatteningPieces(b, beside_fold[k]);
      CurveSample previous{snapped(b[0]), static_cast<double>(k)};
      for (int p = 1; p <= pieces; ++p) {
        const double t = static_cast<double>(p) / pieces;
        const CurveSample next{snapped(bezierPoint(b, t)), k + t};
        collector.addPiece(previous, next);
        previous = next;
      }
    }
    collector.flush();
    if (segments > 0) extendEndsLeavingTheImage(curve, image, scale, collector);
  }
}

}  // namespace vicc_glyphs
