#include "vicc_glyphs/pacemod/offset_contour.hpp"

#include <algorithm>
#include <clipper.hpp>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <stdexcept>
#include <utility>

#include "vicc_glyphs/pacemod/polygon_crossings.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

// Clipper works on integers: 1/1024 pixel keeps the rounding far below anything visible, and
// coordinates of any glyph stay in its fast 32-bit range.
constexpr double kUnitsPerPixel = 1024.0;
// The round joins' arcs (around reflex corners of an inset, convex ones of an inflation) stay
// this close to the true circle.
constexpr double kArcTolerancePx = 0.005;
// The isoline is handed on as a polyline with about this spacing: long straight edges get
// points for the least-squares fit's every span.
constexpr double kSpacingPx = 0.25;
// Newton steps onto a raster isoline's exact position: one lands on the nearest contour point's
// circle, more only where the nearest point moves (around a corner of the isoline).
constexpr int kProjectionSteps = 4;
// A chord between two projected points whose middle is this far off the isoline cuts a corner.
constexpr double kCornerCutPx = 0.005;
// Between two projected points the isoline may bend away from their chord by this much before
// a point goes in between (a raster of 2 px cells leaves chords of 2 px: on an arc of radius
// 10 px they are 0.05 px off).
constexpr double kSagittaPx = 0.02;
constexpr int kBendRefinements = 4;
constexpr double kSamePointPx = 1e-9;

using ClipperLib::Path;
using ClipperLib::Paths;

bool allFinite(const Polyline& line) {
  return std::all_of(line.begin(), line.end(), [](const Point2& p) { return p.allFinite(); });
}

Path toPath(const Polyline& line) {
  Path path;
  for (const Point2& p : line) {
    path.emplace_back(static_cast<ClipperLib::cInt>(std::llround(p.x() * kUnitsPerPixel)),
                      static_cast<ClipperLib::cInt>(std::llround(p.y() * kUnitsPerPixel)));
  }
  return path;
}

// The area a closed polyline encloses (non-zero winding: a loop of the curve in its own
// direction belongs to it), as simple polygons.
Paths regionOf(const Polyline& contour) {
  Paths region;
  ClipperLib::SimplifyPolygon(toPath(contour), region, ClipperLib::pftNonZero);
  return region;
}

// Every point within `offset_px` of `region` (> 0), or every point of it farther than
// -offset_px from its outside (< 0): Minkowski sum or difference with a disc, exact up to the
// integer grid and the arcs' tolerance.
Paths offsetRegion(const Paths& region, double offset_px) {
  ClipperLib::ClipperOffset offsetter(2.0, kArcTolerancePx * kUnitsPerPixel);
  offsetter.AddPaths(region, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
  Paths result;
  offsetter.Execute(result, offset_px * kUnitsPerPixel);
  return result;
}

double totalArea(const Paths& paths) {
  double area = 0.0;
  for (const Path& path : paths) area += ClipperLib::Area(path);
  return area;
}

// `corners` (closed) with points inserted so that none are more than kSpacingPx apart.
Polyline resampled(const Polyline& corners) {
  Polyline result;
  if (corners.size() < 2) return result;
  for (std::size_t i = 0; i + 1 < corners.size(); ++i) {
    const int steps =
        std::max(1, static_cast<int>(std::ceil((corners[i + 1] - corners[i]).norm() / kSpacingPx)));
    for (int k = 0; k < steps; ++k) {
      result.push_back(corners[i] + (corners[i + 1] - corners[i]) * (double(k) / steps));
    }
  }
  result.push_back(result.front());
  return result;
}

// The largest polygon of `paths` as a closed polyline with points at most kSpacingPx apart.
Polyline largestAsPolyline(const Paths& paths) {
  const auto largest =
      std::max_element(paths.begin(), paths.end(), [](const Path& a, const Path& b) {
        return std::abs(ClipperLib::Area(a)) < std::abs(ClipperLib::Area(b));
      });
  if (largest == paths.end() || largest->size() < 3) return {};
  Polyline corners;
  for (const ClipperLib::IntPoint& p : *largest) {
    corners.emplace_back(p.X / kUnitsPerPixel, p.Y / kUnitsPerPixel);
  }
  corners.push_back(corners.front());
  return resampled(corners);
}

// `line` turned to run the way `contour` does; empty when it is too short for a fit.
Polyline orientedLike(Polyline line, const Polyline& contour) {
  if (line.size() < 8) return {};
  if ((polylineArea(line) > 0.0) != (polylineArea(contour) > 0.0)) {
    std::reverse(line.begin(), line.end());
  }
  return line;
}

// The raster the region is traced on for offsetIsoline: image position of its corner, grid
// pixels per image pixel, size.
struct IsolineGrid {
  Point2 origin = Point2::Zero();
  double scale = 1.0;
  cv::Size size;
};

// About kGridCells grid pixels across the contour's box (a finer grid for a small contour, at
// most 4 per image pixel, not coarser than the image unless that takes over kMaxGridCells): the
// raster only has to find the isoline's topology and each point within a grid pixel or two, the
// projection does the rest. (512 cells gave the same curves at twice the cost; the approximate 5x5
// distance mask is off by ~2 % of the distance, which the projection removes as well.)
constexpr double kGridCells = 256.0;
constexpr double kMaxGridCells = 2048.0;  // a huge inflation must not allocate gigabytes
constexpr int kSubpixelBits = 8;

IsolineGrid gridAround(const Polyline& contour, double margin) {
  Point2 low = contour.front(), high = contour.front();
  for (const Point2& p : contour) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  low -= Point2::Constant(margin);
  high += Point2::Constant(margin);
  const double extent = std::max(high.x() - low.x(), high.y() - low.y());
  const double scale = std::min(std::clamp(kGridCells / std::max(extent, 1e-9), 0.5, 4.0),
                                kMaxGridCells / std::max(extent, 1e-9));
  return {low, scale,
          cv::Size(static_cast<int>(std::ceil((high.x() - low.x()) * scale)) + 1,
                   static_cast<int>(std::ceil((high.y() - low.y()) * scale)) + 1)};
}

// The region within `offset` of the contour's region (or farther than -offset inside it) on
// `grid`: a distance transform of the side the offset lies on, to the other side's pixel
// centres, less half a pixel (the boundary between them).
cv::Mat offsetRegionRaster(const Polyline& contour, const IsolineGrid& grid, double offset) {
  std::vector<cv::Point> polygon;
  const double unit = 1 << kSubpixelBits;
  for (const Point2& p : contour) {
    const Point2 g = (p - grid.origin) * grid.scale - Point2::Constant(0.5);
    polygon.emplace_back(static_cast<int>(std::lround(g.x() * unit)),
                         static_cast<int>(std::lround(g.y() * unit)));
  }
  cv::Mat inside = cv::Mat::zeros(grid.size, CV_8U);
  cv::fillPoly(inside, std::vector<std::vector<cv::Point>>{polygon}, 255, cv::LINE_8,
               kSubpixelBits);
  const double threshold = std::abs(offset) * grid.scale + 0.5;
  cv::Mat distance;
  if (offset > 0.0) {
    cv::distanceTransform(255 - inside, distance, cv::DIST_L2, cv::DIST_MASK_5);
    return distance < threshold;
  }
  cv::distanceTransform(inside, distance, cv::DIST_L2, cv::DIST_MASK_5);
  return distance > threshold;
}

// The outline of the largest part of `region`, as image points at the grid pixels' centres.
Polyline traceLargest(const cv::Mat& region, const IsolineGrid& grid) {
  std::vector<std::vector<cv::Point>> traced;
  cv::findContours(region, traced, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
  const auto largest =
      std::max_element(traced.begin(), traced.end(), [](const auto& a, const auto& b) {
        return std::abs(cv::contourArea(a)) < std::abs(cv::contourArea(b));
      });
  Polyline result;
  if (largest == traced.end() || largest->size() < 8) return result;
  for (const cv::Point& p : *largest) {
    result.push_back(grid.origin + (Point2(p.x, p.y) + Point2::Constant(0.5)) / grid.scale);
  }
  return result;
}

// The normal (unnormalised) of `contour`'s segment towards the offset's side, which
// `outward_is_right` gives (+1: right of the direction of travel, -1: left).
Point2 offsetSideNormal(const Polyline& contour, int segment, double outward_is_right) {
  const Point2 along = contour[segment + 1] - contour[segment];
  return outward_is_right * Point2(-along.y(), along.x());
}

// Whether `away` (from the nearest point of `contour`, on `segment`) points to the offset's
// side. At a vertex, either segment meeting there will do: a point beyond a segment's end is
// beside its neighbour.
bool onOffsetSide(const Polyline& contour, int segment, const Point2& foot, const Point2& away,
                  double outward_is_right) {
  const auto side = [&](int i) {
    return away.dot(offsetSideNormal(contour, i, outward_is_right)) > 0.0;
  };
  if (side(segment)) return true;
  const int last = static_cast<int>(contour.size()) - 2;  // closed: last segment meets the first
  if (foot == contour[segment]) return side(segment > 0 ? segment - 1 : last);
  if (foot == contour[segment + 1]) return side(segment < last ? segment + 1 : 0);
  return false;
}

// Projects points onto the isoline at `offset` from `contour` (a Newton step on the distance:
// from the nearest contour point outward to |offset|, repeated while that nearest point moves).
// A point the raster put on the wrong side of the contour (an offset below a grid pixel) goes
// along the nearest segment's normal to the offset's side.
class IsolineProjection {
 public:
  IsolineProjection(const Polyline& contour, double offset)
      : contour_(contour),
        distance_(std::abs(offset)),
        nearest_(contour, std::max(4.0, distance_ / 4.0)),
        // Positive shoelace area (clockwise on screen, y down): the enclosed region on the right.
        outward_is_right_((polylineArea(contour) > 0.0) == (offset < 0.0) ? 1.0 : -1.0) {}

  /// `p` on the isoline; `foot` its nearest contour point.
  Point2 project(Point2 p, Point2* foot = nullptr) const {
    Point2 nearest = p;
    for (int step = 0; step < kProjectionSteps; ++step) {
      int segment = -1;
      nearest = nearest_.nearest(p, &segment);
      if (segment < 0) break;
      Point2 away = p - nearest;
      if (!onOffsetSide(contour_, segment, nearest, away, outward_is_right_)) {
        away = offsetSideNormal(contour_, segment, outward_is_right_);
      }
      if (!(away.norm() > 0.0)) break;
      const Point2 next = nearest + away.normalized() * distance_;
      const bool settled = (next - p).norm() < 1e-4;
      p = next;
      if (settled) break;
    }
    if (foot) *foot = nearest;
    return p;
  }

  /// The corner of the isoline between `a` and `b` (feet `foot_a`, `foot_b`) where the chord
  /// between them cuts one (their feet jump along the contour, and the chord's middle is off
  /// the isoline): the meeting point of the isoline's tangents there, projected.
  std::optional<Point2> cornerBetween(const Point2& a, const Point2& foot_a, const Point2& b,
                                      const Point2& foot_b, Point2* foot) const {
    if ((foot_a - foot_b).norm() <= 2.0 * (a - b).norm() + 1e-9) return std::nullopt;
    if (std::abs(nearest_(0.5 * (a + b)) - distance_) < kCornerCutPx) return std::nullopt;
    const Point2 normal_a = (a - foot_a).normalized(), normal_b = (b - foot_b).normalized();
    const double determinant = cross(normal_a, normal_b);
    if (std::abs(determinant) < 1e-6) return std::nullopt;
    // x . normal_a = a . normal_a and x . normal_b = b . normal_b (Cramer's rule).
    const double ca = a.dot(normal_a), cb = b.dot(normal_b);
    const Point2 corner((ca * normal_b.y() - cb * normal_a.y()) / determinant,
                        (normal_a.x() * cb - normal_b.x() * ca) / determinant);
    if ((corner - 0.5 * (a + b)).norm() > (a - b).norm()) return std::nullopt;
    return project(corner, foot);
  }

  /// Appends what the isoline needs from `a` to `b` (both on it, feet `foot_a` and `foot_b`;
  /// `line` ends at `a`):
  /// the corner between them if there is one, and where the isoline bends away from a chord by
  /// more than kSagittaPx (an arc that turns by t over a chord c: about c t / 8), the chord's
  /// projected middle (at most kBendRefinements times over); then `b`. Around a corner the
  /// corner's foot lies on one of the two branches: the other side gets a few points more.
  void appendPiece(const Point2& a, const Point2& foot_a, const Point2& b, const Point2& foot_b,
                   Polyline& line, int refinements = kBendRefinements) const {
    Point2 corner_foot;
    if (auto corner = cornerBetween(a, foot_a, b, foot_b, &corner_foot)) {
      appendBend(a, foot_a, *corner, corner_foot, line, refinements);
      appendBend(*corner, corner_foot, b, foot_b, line, refinements);
      return;
    }
    appendBend(a, foot_a, b, foot_b, line, refinements);
  }

 private:
  void appendBend(const Point2& a, const Point2& foot_a, const Point2& b, const Point2& foot_b,
                  Polyline& line, int refinements) const {
    const Point2 normal_a = a - foot_a, normal_b = b - foot_b;
    const double turn = std::abs(std::atan2(cross(normal_a, normal_b), normal_a.dot(normal_b)));
    if (refinements > 0 && (a - b).norm() * turn / 8.0 > kSagittaPx) {
      Point2 foot;
      const Point2 middle = project(0.5 * (a + b), &foot);
      appendPiece(a, foot_a, middle, foot, line, refinements - 1);
      appendPiece(middle, foot, b, foot_b, line, refinements - 1);
      return;
    }
    // A corner found again between points next to it projects onto itself: no repeated point.
    if ((b - line.back()).norm() > kSamePointPx) line.push_back(b);
  }

  const Polyline& contour_;
  double distance_;
  PolylineDistance nearest_;
  double outward_is_right_;
};

// The raster's isoline points on the exact isoline, with the corners the raster's steps cut and
// the points its bends need, resampled to at most kSpacingPx apart, without small loops.
Polyline projectOntoIsoline(const Polyline& points, const Polyline& contour, double offset) {
  const IsolineProjection projection(contour, offset);
  Polyline projected, feet(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    projected.push_back(projection.project(points[i], &feet[i]));
  }
  Polyline isoline{projected.front()};
  for (std::size_t i = 0; i < projected.size(); ++i) {
    const std::size_t j = (i + 1) % projected.size();
    projection.appendPiece(projected[i], feet[i], projected[j], feet[j], isoline);
  }
  return withoutHairs(withoutSmallLoops(resampled(isoline)));
}

}  // namespace

// `line` (closed) with every loop of at most kLoopPx cut out at its crossing: projecting onto
// the exact isoline folds its cusps (where the offsets of two lobes meet) into loops of a few
// hundredths of a pixel, and a fitted curve that follows them crosses itself. The isoline of a
// region bounds it: it has no loop of its own.
Polyline withoutSmallLoops(Polyline line) {
  constexpr double kLoopPx = 1.0;
  for (bool cut = true; cut;) {
    cut = false;
    for (const Crossing& crossing : findCrossings({line})) {
      const int first = crossing.a.segment, last = crossing.b.segment;  // first < last
      double loop = 0.0;
      for (int i = first + 1; i < last && loop <= kLoopPx; ++i) {
        loop += (line[i + 1] - line[i]).norm();
      }
      if (loop > kLoopPx) continue;  // a loop across the closing point, or a large one: kept
      const Point2 at = crossingPoint({line}, crossing);
      line.erase(line.begin() + first + 1, line.begin() + last + 1);
      line.insert(line.begin() + first + 1, at);
      cut = true;
      break;  // the indices of the other crossings have moved
    }
  }
  return line;
}

// `line` (closed) without its hairs: stretches that run out and back along themselves, their
// two sides closer than kHairWidthPx and enclosing (with the gap) less than that width times
// their length. Where two parts of the offset region nearly touch, the raster's trace runs into
// the crack between them and out again; a fitted curve cannot follow both sides of a zero-width
// crack without crossing itself, and the crack holds no area of the region.
Polyline withoutHairs(const Polyline& line) {
  constexpr double kHairWidthPx = 0.25;
  constexpr double kLongestHairPx = 80.0;  // both sides
  if (line.size() < 5) return line;
  const std::vector<Point2> ring(line.begin(), line.end() - 1);
  const long n = static_cast<long>(ring.size());
  // Arc length at each point and the prefix sums of the shoelace terms (the whole at n).
  std::vector<double> at(n + 1, 0.0), shoelace(n + 1, 0.0);
  for (long i = 0; i < n; ++i) {
    const Point2 &p = ring[i], &q = ring[(i + 1) % n];
    at[i + 1] = at[i] + (q - p).norm();
    shoelace[i + 1] = shoelace[i] + cross(p, q);
  }
  const auto forward = [&](const std::vector<double>& sums, long i, long j) {
    return j >= i ? sums[j] - sums[i] : sums[n] - sums[i] + sums[j];
  };
  // Per point the farthest point along the line that ends a hair from it. A hair's two ends lie
  // within its width: a sweep over the points in x order meets every such pair.
  std::vector<long> by_x(n);
  for (long i = 0; i < n; ++i) by_x[i] = i;
  std::sort(by_x.begin(), by_x.end(), [&](long a, long b) { return ring[a].x() < ring[b].x(); });
  std::vector<long> tip_end(n, -1);
  std::vector<double> longest(n, 0.0);
  for (long a = 0; a < n; ++a) {
    for (long b = a + 1; b < n && ring[by_x[b]].x() - ring[by_x[a]].x() < kHairWidthPx; ++b) {
      const long p = by_x[a], q = by_x[b];
      if ((ring[q] - ring[p]).norm() >= kHairWidthPx) continue;
      for (const auto& [i, j] : {std::make_pair(p, q), std::make_pair(q, p)}) {
        const double along = forward(at, i, j);  // from i forward to j
        if (along <= 2.0 * kHairWidthPx || along > kLongestHairPx || along <= longest[i]) continue;
        const double area = 0.5 * std::abs(forward(shoelace, i, j) + cross(ring[j], ring[i]));
        if (area < kHairWidthPx * along) {
          tip_end[i] = j;
          longest[i] = along;
        }
      }
    }
  }
  std::vector<char> removed(n, 0);
  for (long i = 0; i < n; ++i) {
    if (removed[i] || tip_end[i] < 0) continue;
    for (long j = (i + 1) % n; j != tip_end[i]; j = (j + 1) % n) removed[j] = 1;
  }
  Polyline kept;
  for (long i = 0; i < n; ++i) {
    if (!removed[i]) kept.push_back(ring[i]);
  }
  if (kept.size() < 4) return line;
  kept.push_back(kept.front());
  return kept;
}

Polyline offsetIsoline(const Polyline& contour, double offset) {
  if (contour.size() < 4 || !std::isfinite(offset) || !allFinite(contour)) return {};
  // Without repeated points (a segment of length 0 has no side to project to), and closed: the
  // raster closes it, and the projection must see the same polygon.
  Polyline closed;
  for (const Point2& p : contour) {
    if (closed.empty() || p != closed.back()) closed.push_back(p);
  }
  if (closed.front() != closed.back()) closed.push_back(closed.front());
  if (closed.size() < 4) return {};
  if (offset == 0.0) return orientedLike(resampled(closed), closed);  // corners and all
  const IsolineGrid grid = gridAround(closed, std::max(offset, 0.0) + 3.0);
  const Polyline traced = traceLargest(offsetRegionRaster(closed, grid, offset), grid);
  if (traced.empty()) return {};
  return orientedLike(projectOntoIsoline(traced, closed, offset), closed);
}

Polyline offsetIsolineAvoiding(const Polyline& contour, double offset,
                               const std::vector<Polyline>& obstacles, double clearance,
                               bool* limited) {
  if (limited) *limited = false;
  if (contour.size() < 4 || !std::isfinite(offset) || !allFinite(contour)) return {};
  Paths region = offsetRegion(regionOf(contour), offset);
  Paths blocked;
  for (const Polyline& obstacle : obstacles) {
    if (obstacle.size() < 4 || !allFinite(obstacle)) continue;
    const Paths part = regionOf(obstacle);
    blocked.insert(blocked.end(), part.begin(), part.end());
  }
  if (!blocked.empty() && std::isfinite(clearance)) {
    const double before = totalArea(region);
    ClipperLib::Clipper clipper;
    clipper.AddPaths(region, ClipperLib::ptSubject, true);
    clipper.AddPaths(offsetRegion(blocked, std::max(clearance, 0.0)), ClipperLib::ptClip, true);
    clipper.Execute(ClipperLib::ctDifference, region, ClipperLib::pftNonZero,
                    ClipperLib::pftNonZero);
    if (limited) *limited = totalArea(region) < before - 1.0;  // one unit^2: anything at all
  }
  return orientedLike(largestAsPolyline(region), contour);
}

}  // namespace pacemod
}  // namespace vicc_glyphs
