// closedBezierFit (declared in offset_contour.hpp): an isoline as a Bezier chain that keeps its
// sharp corners.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "vicc_glyphs/bspline/bezier_conversion.hpp"
#include "vicc_glyphs/bspline/fitting.hpp"
#include "vicc_glyphs/bspline/fowler_bartels.hpp"
#include "vicc_glyphs/pacemod/offset_contour.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

// A corner turns the line by more than this within kCornerReachPx before and after it. A smooth
// least-squares cubic rounds such a corner over a knot span, and where the corner is a cusp (the
// inner offset of a wavy contour, where the offsets of two lobes meet) it overshoots into a
// swallowtail that crosses itself: the renderer draws that with the curve's sides swapped, a
// smudge of one side's colour in the other.
constexpr double kCornerTurnDegrees = 60.0;
constexpr double kCornerReachPx = 1.0;
// Of two corners closer than this (px) along the line only the sharper one is kept.
constexpr double kCornerSeparationPx = 2.0;

double lengthOf(const Polyline& line) {
  double length = 0.0;
  for (std::size_t i = 0; i + 1 < line.size(); ++i) length += (line[i + 1] - line[i]).norm();
  return length;
}

// The least-squares cubic on `spans` uniform knot spans (clamped) of the points of `line` at
// their chord-length parameters in [0, 1].
bspline::BSplineCurve leastSquaresCubic(const Polyline& line, int spans) {
  const std::vector<double> knots =
      bspline::BSplineCurve::clampedUniformKnots(3, spans + 3, 0.0, 1.0);
  // Banded normal equations: tens of points per span determine the curve well, and a sparse QR
  // of a traced isoline (thousands of points) cost as much as the distance transform.
  const bspline::CubicLeastSquares solver(
      bspline::BSplineCurve(3, knots, std::vector<Point2>(knots.size() - 4, Point2::Zero())),
      bspline::chordLengthParameters(line, 0.0, 1.0));
  Eigen::MatrixX2d targets(static_cast<Eigen::Index>(line.size()), 2);
  for (std::size_t i = 0; i < line.size(); ++i) targets.row(static_cast<Eigen::Index>(i)) = line[i];
  return bspline::BSplineCurve(3, knots, solver.solvePoints(targets));
}

// The least-squares cubic with knots about `knot_spacing` apart, closed at its start with equal
// end tangents; `line` is closed (first == last point).
std::vector<Point2> fitClosedChain(const Polyline& line, double knot_spacing) {
  const int spans = std::clamp(static_cast<int>(std::lround(lengthOf(line) / knot_spacing)), 4,
                               static_cast<int>(line.size()) / 2);
  const bspline::BSplineCurve fit = leastSquaresCubic(line, spans);
  // Close it exactly with equal end tangents (the fit leaves both ends free).
  const Point2 start = 0.5 * (fit.pointAt(0.0) + fit.pointAt(1.0));
  const Point2 tangent = 0.5 * (fit.derivativeAt(0.0) + fit.derivativeAt(1.0));
  return bspline::bsplineToBezierChain(
             bspline::fowlerBartelsModify(
                 fit, {{0.0, start, 0}, {1.0, start, 0}, {0.0, tangent, 1}, {1.0, tangent, 1}}))
      .control_points;
}

// The least-squares cubic through both end points of the open `piece`, knots about
// `knot_spacing` apart (at least 4 points per span; fewer spans where the points leave one
// undetermined); a straight segment for a piece too short to determine a curve.
std::vector<Point2> fitOpenChain(const Polyline& piece, double knot_spacing) {
  const Point2 a = piece.front(), b = piece.back();
  for (int spans = std::min(static_cast<int>(std::lround(lengthOf(piece) / knot_spacing)),
                            static_cast<int>(piece.size()) / 4);
       spans >= 1; spans /= 2) {
    try {
      std::vector<Point2> chain = bspline::bsplineToBezierChain(
                                      bspline::fowlerBartelsModify(leastSquaresCubic(piece, spans),
                                                                   {{0.0, a, 0}, {1.0, b, 0}}))
                                      .control_points;
      if (std::all_of(chain.begin(), chain.end(), [](const Point2& p) { return p.allFinite(); })) {
        return chain;
      }
    } catch (const std::invalid_argument&) {
      // A span without enough points: try fewer.
    }
  }
  return {a, a + (b - a) / 3.0, a + 2.0 * (b - a) / 3.0, b};
}

// The distinct points of a closed line (its last point repeats the first) and the arc length
// at each.
struct Ring {
  std::vector<Point2> points;
  std::vector<double> at;
  double length = 0.0;
  explicit Ring(const Polyline& line) : points(line.begin(), line.end() - 1) {
    for (std::size_t i = 0; i < points.size(); ++i) {
      at.push_back(length);
      length += (points[(i + 1) % points.size()] - points[i]).norm();
    }
  }
  std::size_t size() const { return points.size(); }
  double ahead(std::size_t from, std::size_t to) const {  // arc length from -> to, forward
    const double d = at[to] - at[from];
    return d >= 0.0 ? d : d + length;
  }
};

// The turn (radians) of the ring at point i: between the chords to the points kCornerReachPx
// behind and ahead of it.
double turnAt(const Ring& ring, std::size_t i) {
  const std::size_t n = ring.size();
  std::size_t back = (i + n - 1) % n, front = (i + 1) % n;
  while (back != i && ring.ahead(back, i) < kCornerReachPx) back = (back + n - 1) % n;
  while (front != i && ring.ahead(i, front) < kCornerReachPx) front = (front + 1) % n;
  const Point2 in = ring.points[i] - ring.points[back], out = ring.points[front] - ring.points[i];
  if (!(in.norm() > 0.0) || !(out.norm() > 0.0)) return 0.0;
  return std::acos(std::clamp(in.dot(out) / (in.norm() * out.norm()), -1.0, 1.0));
}

// The corners of the ring, in order along it.
std::vector<std::size_t> sharpCorners(const Ring& ring) {
  const double limit = kCornerTurnDegrees * M_PI / 180.0;
  std::vector<std::pair<double, std::size_t>> candidates;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const double turn = turnAt(ring, i);
    if (turn > limit) candidates.push_back({turn, i});
  }
  std::sort(candidates.rbegin(), candidates.rend());  // sharpest first
  std::vector<std::size_t> corners;
  for (const auto& candidate : candidates) {
    const bool near = std::any_of(corners.begin(), corners.end(), [&](std::size_t c) {
      return std::min(ring.ahead(c, candidate.second), ring.ahead(candidate.second, c)) <
             kCornerSeparationPx;
    });
    if (!near) corners.push_back(candidate.second);
  }
  std::sort(corners.begin(), corners.end());
  return corners;
}

}  // namespace

std::vector<Point2> closedBezierFit(const Polyline& line, double knot_spacing) {
  if (line.size() < 5) throw std::invalid_argument("closedBezierFit: need at least 4 points");
  const Ring ring(line);
  const std::vector<std::size_t> corners = sharpCorners(ring);
  if (corners.empty()) return fitClosedChain(line, knot_spacing);
  // One open fit from each corner to the next; they meet at the corners (C0).
  std::vector<Point2> chain{ring.points[corners.front()]};
  for (std::size_t k = 0; k < corners.size(); ++k) {
    const std::size_t from = corners[k], to = corners[(k + 1) % corners.size()];
    Polyline piece{ring.points[from]};
    for (std::size_t i = (from + 1) % ring.size(); i != to; i = (i + 1) % ring.size()) {
      piece.push_back(ring.points[i]);
    }
    piece.push_back(ring.points[to]);
    const std::vector<Point2> part = fitOpenChain(piece, knot_spacing);
    chain.insert(chain.end(), part.begin() + 1, part.end());
  }
  return chain;
}

}  // namespace pacemod
}  // namespace vicc_glyphs
