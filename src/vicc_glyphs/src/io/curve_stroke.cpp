#include "curve_stroke.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "cubic_bezier.hpp"
#include "svg_arc.hpp"

namespace vicc_glyphs {
namespace io_detail {
namespace {

using Cubic = std::array<Point2, 4>;
using Polygon = std::vector<Point2>;

constexpr double kPi = 3.14159265358979323846;
constexpr int kSearchGrid = 64;   // samples per cubic when looking for split points
constexpr int kMaxFitDepth = 12;  // an offset piece is halved at most this often
constexpr int kMaxSampleDepth = 12;
constexpr int kFitSamples = 25;  // true-offset points per least-squares fit and error check
constexpr double kMaxSampleTurn = 10.0 * kPi / 180.0;  // centreline polyline: turn per step
constexpr double kCuspSpeed = 1e-6;  // |B'| below this x the control polygon's size: a cusp

Point2 leftNormal(const Point2& v) { return Point2(-v.y(), v.x()); }
Point2 rotated(const Point2& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return Point2(c * v.x() - s * v.y(), s * v.x() + c * v.y());
}

struct Tolerances {
  double fit;      // offset cubics against the true offset (user units)
  double flatten;  // chords against the offset cubics, arcs
  double centre;   // the centreline polyline: an inner edge shared by pieces, only kept inside
};

// One centreline cubic; `scale` (control polygon size) sizes the "zero derivative" tests.
struct Segment : CubicBezier {
  double scale = 1.0;

  // Unit tangent; where the derivative vanishes (coincident control points, a cusp) the
  // direction of the next derivative as seen from side `from` (-1 before t, +1 after).
  Point2 tangent(double t, double from) const {
    const double eps = 1e-9 * scale;
    for (const Point2& v : {d1(t), Point2(from * d2(t)), d3()}) {
      if (v.norm() > eps) return v.normalized();
    }
    return Point2(1.0, 0.0);
  }
  Point2 offsetAt(double t, double offset, double from) const {
    return at(t) + offset * leftNormal(tangent(t, from));
  }
  // True where the offset runs backwards: radius of curvature below |offset| on its side.
  bool folds(double t, double offset) const {
    return offset * cross(d1(t), d2(t)) > std::pow(d1(t).norm(), 3);
  }
};

// Appends the roots of f where its sign changes between neighbouring grid parameters.
void signChanges(const std::function<double(double)>& f, const std::vector<double>& grid,
                 std::vector<double>& roots) {
  for (std::size_t i = 0; i + 1 < grid.size(); ++i) {
    double a = grid[i], b = grid[i + 1];
    const bool positive = f(a) > 0.0;
    if ((f(b) > 0.0) == positive) continue;
    for (int k = 0; k < 60 && b - a > 1e-15; ++k) {
      const double m = 0.5 * (a + b);
      ((f(m) > 0.0) == positive ? a : b) = m;
    }
    roots.push_back(0.5 * (a + b));
  }
}

std::vector<double> uniformGrid() {
  std::vector<double> grid;
  for (int i = 0; i <= kSearchGrid; ++i) grid.push_back(static_cast<double>(i) / kSearchGrid);
  return grid;
}

// Local extrema of |B'|: exact cusps, and the seeds of narrow tight turns near cusps.
std::vector<double> speedExtrema(const Segment& s) {
  std::vector<double> extrema;
  signChanges([&](double t) { return s.d1(t).dot(s.d2(t)); }, uniformGrid(), extrema);
  return extrema;
}

// Where a piece of the offset must end: inflections, and where the radius of curvature
// crosses `half` (the inner offset starts or stops folding back). Sorted, from 0 to 1.
std::vector<double> splitParameters(const Segment& s, double half) {
  std::vector<double> grid = uniformGrid();
  const std::vector<double> extrema = speedExtrema(s);
  grid.insert(grid.end(), extrema.begin(), extrema.end());
  std::sort(grid.begin(), grid.end());
  std::vector<double> ts = {0.0, 1.0};
  signChanges([&](double t) { return cross(s.d1(t), s.d2(t)); }, grid, ts);
  signChanges(
      [&](double t) {
        return half * std::abs(cross(s.d1(t), s.d2(t))) - std::pow(s.d1(t).norm(), 3);
      },
      grid, ts);
  std::sort(ts.begin(), ts.end());
  ts.erase(std::unique(ts.begin(), ts.end(), [](double a, double b) { return b - a < 1e-9; }),
           ts.end());
  ts.back() = 1.0;
  return ts;
}

// de Casteljau split at t.
std::array<Cubic, 2> splitCubic(const Cubic& b, double t) {
  const Point2 ab = b[0] + t * (b[1] - b[0]), bc = b[1] + t * (b[2] - b[1]);
  const Point2 cd = b[2] + t * (b[3] - b[2]);
  const Point2 abc = ab + t * (bc - ab), bcd = bc + t * (cd - bc);
  const Point2 mid = abc + t * (bcd - abc);
  return {Cubic{b[0], ab, abc, mid}, Cubic{mid, bcd, cd, b[3]}};
}

Segment makeSegment(const Cubic& b) {
  double scale = 0.0;
  for (const Point2& p : b) scale = std::max(scale, (p - b[0]).norm());
  return {{b}, scale};
}

// The subpath's cubics without zero-length ones, split at exact cusps: the direction flips
// there, which the stroke treats as a join between two segments (as Clipper's polyline does).
std::vector<Segment> segmentsOf(const Contour& points) {
  std::vector<Segment> segments;
  for (std::size_t k = 0; k + 3 < points.size(); k += 3) {
    Segment s = makeSegment({points[k], points[k + 1], points[k + 2], points[k + 3]});
    if (!std::isfinite(s.scale)) throw std::invalid_argument("stroke coordinates out of range");
    if (s.scale <= 1e-12 * std::max(1.0, s.b[0].norm())) continue;
    const Segment original = s;
    double done = 0.0;  // parameter of s.b's start on the original cubic
    for (const double t : speedExtrema(original)) {
      if (t < 1e-6 || t > 1.0 - 1e-6 || original.d1(t).norm() > kCuspSpeed * original.scale) {
        continue;
      }
      const std::array<Cubic, 2> halves = splitCubic(s.b, (t - done) / (1.0 - done));
      segments.push_back(makeSegment(halves[0]));
      s = makeSegment(halves[1]);
      done = t;
    }
    segments.push_back(s);
  }
  return segments;
}

// A cubic from p0 (direction t0) to p3 (arriving along t3) through the samples q at chord-length
// parameters u: Schneider's least squares for the two inner control lengths.
Cubic fitCubic(const Point2& p0, const Point2& t0, const Point2& p3, const Point2& t3,
               const std::vector<Point2>& q, const std::vector<double>& u) {
  double c11 = 0.0, c12 = 0.0, c22 = 0.0, x1 = 0.0, x2 = 0.0;
  for (std::size_t i = 0; i < q.size(); ++i) {
    const double v = 1.0 - u[i];
    const double b0 = v * v * v, b1 = 3.0 * v * v * u[i], b2 = 3.0 * v * u[i] * u[i];
    const double b3 = u[i] * u[i] * u[i];
    const Point2 a1 = b1 * t0, a2 = -b2 * t3;
    const Point2 r = q[i] - (b0 + b1) * p0 - (b2 + b3) * p3;
    c11 += a1.dot(a1), c12 += a1.dot(a2), c22 += a2.dot(a2);
    x1 += a1.dot(r), x2 += a2.dot(r);
  }
  const double det = c11 * c22 - c12 * c12;
  double alpha = (p3 - p0).norm() / 3.0, beta = alpha;
  if (std::abs(det) > 1e-12 * c11 * c22) {
    const double a = (x1 * c22 - x2 * c12) / det, b = (c11 * x2 - c12 * x1) / det;
    // Negative lengths would loop; the thirds fallback then fails the check and is halved.
    if (a > 0.0 && b > 0.0) alpha = a, beta = b;
  }
  return {p0, p0 + alpha * t0, p3 - beta * t3, p3};
}

// Largest distance from the samples to the cubic (Newton projection from their parameters).
double fitError(const Cubic& cubic, const std::vector<Point2>& q, const std::vector<double>& u) {
  const Segment c = makeSegment(cubic);
  double worst = 0.0;
  for (std::size_t i = 0; i < q.size(); ++i) {
    double t = u[i];
    for (int k = 0; k < 3; ++k) {
      const Point2 d = c.at(t) - q[i], d1 = c.d1(t);
      const double slope = d1.squaredNorm() + d.dot(c.d2(t));
      if (slope > 0.0) t = std::clamp(t - d.dot(d1) / slope, 0.0, 1.0);
    }
    worst = std::max(worst, (c.at(t) - q[i]).norm());
  }
  return worst;
}

// Appends to `chain` (ending at the offset point of ta) cubics within `tolerance` of the true
// offset on [ta, tb]: its end points and tangents, inner lengths fitted; halved where it misses.
void fitOffset(const Segment& s, double offset, double ta, double tb, double tolerance, int depth,
               Contour& chain) {
  const double direction = s.folds(0.5 * (ta + tb), offset) ? -1.0 : 1.0;
  const Point2 p0 = chain.back(), p3 = s.offsetAt(tb, offset, -1.0);
  std::vector<Point2> q;
  std::vector<double> u = {0.0};
  for (int i = 1; i <= kFitSamples; ++i) {
    q.push_back(s.offsetAt(ta + (tb - ta) * i / (kFitSamples + 1), offset, 1.0));
    u.push_back(u.back() + (q.back() - (i == 1 ? p0 : q[i - 2])).norm());
  }
  const double length = u.back() + (p3 - q.back()).norm();
  for (double& v : u) v = length > 0.0 ? v / length : 0.0;
  u.erase(u.begin());
  const Cubic cubic =
      fitCubic(p0, direction * s.tangent(ta, 1.0), p3, direction * s.tangent(tb, -1.0), q, u);
  if (depth < kMaxFitDepth && fitError(cubic, q, u) > tolerance) {
    const double tm = 0.5 * (ta + tb);
    fitOffset(s, offset, ta, tm, tolerance, depth + 1, chain);
    fitOffset(s, offset, tm, tb, tolerance, depth + 1, chain);
    return;
  }
  chain.insert(chain.end(), {cubic[1], cubic[2], cubic[3]});
}

// Appends the centreline parameters on (ta, tb]: steps turning <= 10 degrees and within
// `tolerance` of their chord (an inner edge two pieces share, so it need only stay inside).
void sampleCentre(const Segment& s, double ta, double tb, double tolerance, int depth,
                  std::vector<double>& ts) {
  const double tm = 0.5 * (ta + tb);
  const Point2 a = s.at(ta), m = s.at(tm), b = s.at(tb);
  auto angle = [](const Point2& x, const Point2& y) {
    return std::acos(std::clamp(x.dot(y), -1.0, 1.0));
  };
  const Point2 tangent_m = s.tangent(tm, 1.0);
  const double turn = angle(s.tangent(ta, 1.0), tangent_m) + angle(tangent_m, s.tangent(tb, -1.0));
  const double chord = (b - a).norm();
  const double bulge = chord > 0.0 ? std::abs(cross(b - a, m - a)) / chord : (m - a).norm();
  if (depth < kMaxSampleDepth && (turn > kMaxSampleTurn || bulge > tolerance)) {
    sampleCentre(s, ta, tm, tolerance, depth + 1, ts);
    sampleCentre(s, tm, tb, tolerance, depth + 1, ts);
    return;
  }
  ts.push_back(tb);
}

// Centre of curvature on the side of `offset`, at most |offset| away: where the folding
// offset turns around. The centreline point where the speed vanishes.
Point2 evoluteAt(const Segment& s, double t, double offset) {
  const Point2 d1 = s.d1(t);
  const double k = cross(d1, s.d2(t)), speed = d1.norm();
  if (!(speed > 0.0) || k == 0.0) return s.at(t);
  const double radius = std::min(speed * speed * speed / std::abs(k), std::abs(offset));
  return s.at(t) + (k > 0.0 ? radius : -radius) * leftNormal(d1) / speed;
}

// Appends polygon b reversed to a.
Polygon closedBy(Polygon a, const Polygon& b) {
  a.insert(a.end(), b.rbegin(), b.rend());
  return a;
}

// Polygons covering one side of a segment, from the centreline to the offset at `offset`.
// Pieces that do not fold join into one polygon (their windings add up, all of one sign);
// a folding piece is cut along its evolute into the part before it and the part beyond
// (opposite windings, kept apart so that the union does not cancel them).
void sideOfSegment(const Segment& s, const std::vector<double>& splits, double offset,
                   const Tolerances& tol, VertexBudget& budget, std::vector<Polygon>& out) {
  Polygon centre = {s.at(0.0)}, outer;
  for (std::size_t i = 0; i + 1 < splits.size(); ++i) {
    const double ta = splits[i], tb = splits[i + 1];
    Contour chain = {s.offsetAt(ta, offset, 1.0)};
    fitOffset(s, offset, ta, tb, tol.fit, 0, chain);
    Polygon flat;
    flattenChain(chain, tol.flatten, budget, flat);
    std::vector<double> ts;
    sampleCentre(s, ta, tb, tol.centre, 0, ts);
    budget.spend(2 * ts.size());
    if (!s.folds(0.5 * (ta + tb), offset)) {
      for (const double t : ts) centre.push_back(s.at(t));
      outer.insert(outer.end(), flat.begin(), flat.end());
      continue;
    }
    if (!outer.empty()) out.push_back(closedBy(centre, outer));
    Polygon before = {s.at(ta)}, evolute = {evoluteAt(s, ta, offset)};
    for (const double t : ts) {
      before.push_back(s.at(t));
      evolute.push_back(evoluteAt(s, t, offset));
    }
    out.push_back(closedBy(before, evolute));
    out.push_back(closedBy(evolute, flat));
    centre = {s.at(tb)};
    outer.clear();
  }
  if (!outer.empty()) out.push_back(closedBy(centre, outer));
}

// Appends the circular arc around `centre` from centre + `from`, turning by `sweep` radians
// (signed), as cubics of at most 90 degrees, flattened.
void appendArc(const Point2& centre, const Point2& from, double sweep, const Tolerances& tol,
               VertexBudget& budget, Polygon& out) {
  const double radius = from.norm();
  Contour chain = {centre + from};
  const std::vector<Point2> cubics =
      centredArcToCubics(centre, radius, radius, 0.0, std::atan2(from.y(), from.x()), sweep,
                         centre + from, centre + rotated(from, sweep));
  chain.insert(chain.end(), cubics.begin(), cubics.end());
  flattenChain(chain, tol.flatten, budget, out);
}

// The wedge a join adds at vertex v (arriving along t1, leaving along t2) on the side of
// `offset` when that is the outer side; on the inner side the two segments' pieces overlap.
void addJoin(const Point2& v, const Point2& t1, const Point2& t2, double offset,
             const StrokeGeometry& stroke, const Tolerances& tol, VertexBudget& budget,
             std::vector<Polygon>& out) {
  const double turn = std::atan2(std::abs(cross(t1, t2)), t1.dot(t2));
  if (turn < 1e-9) return;
  const bool u_turn = std::abs(cross(t1, t2)) < 1e-12 && t1.dot(t2) < 0.0;
  if (!u_turn && offset * cross(t1, t2) > 0.0) return;
  const Point2 n1 = offset * leftNormal(t1), n2 = offset * leftNormal(t2);
  Polygon wedge = {v, v + n1};
  if (stroke.join == LineJoin::kRound) {
    // Round the outside: from n1 towards t1 (a U-turn's half disc lies ahead).
    appendArc(v, n1, cross(n1, t1) > 0.0 ? turn : -turn, tol, budget, wedge);
  } else if (stroke.join == LineJoin::kMiter) {
    // SVG: miter length / width = 1 / sin(angle between the segments / 2); beyond: bevel.
    const double ratio = 1.0 / std::cos(0.5 * turn);
    if (ratio <= std::max(stroke.miter_limit, 1.0)) {
      wedge.push_back(v + (n1 + n2).normalized() * std::abs(offset) * ratio);
    }
  }
  wedge.push_back(v + n2);
  out.push_back(std::move(wedge));
}

// The cap at end point p of an open subpath, `away` pointing out of the stroke.
void addCap(const Point2& p, const Point2& away, double half, LineCap cap, const Tolerances& tol,
            VertexBudget& budget, std::vector<Polygon>& out) {
  if (cap == LineCap::kButt) return;
  const Point2 n = half * leftNormal(away);
  // p itself is a vertex, as in the side polygons: a T-junction there left a hairline crack.
  Polygon shape = {p, p + n};
  if (cap == LineCap::kSquare) {
    shape.push_back(p + n + half * away);
    shape.push_back(p - n + half * away);
  } else {
    appendArc(p, n, -kPi, tol, budget, shape);  // from +n through `away` to -n
  }
  shape.push_back(p - n);
  out.push_back(std::move(shape));
}

void strokeSubpath(const Subpath& subpath, const StrokeGeometry& stroke, const Tolerances& tol,
                   VertexBudget& budget, std::vector<Polygon>& out) {
  const std::vector<Segment> segments = segmentsOf(subpath.points);
  if (segments.empty()) return;
  const double half = 0.5 * stroke.width;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const Segment& s = segments[i];
    const std::vector<double> splits = splitParameters(s, half);
    for (const double offset : {half, -half}) sideOfSegment(s, splits, offset, tol, budget, out);
    const bool last = i + 1 == segments.size();
    if (last && !subpath.closed) continue;
    const Segment& next = segments[last ? 0 : i + 1];
    for (const double offset : {half, -half}) {
      addJoin(s.b[3], s.tangent(1.0, -1.0), next.tangent(0.0, 1.0), offset, stroke, tol, budget,
              out);
    }
  }
  if (subpath.closed) return;
  addCap(segments.front().b[0], -segments.front().tangent(0.0, 1.0), half, stroke.cap, tol, budget,
         out);
  addCap(segments.back().b[3], segments.back().tangent(1.0, -1.0), half, stroke.cap, tol, budget,
         out);
}

// Pixel integers of a user-space polygon, turned to positive orientation (each polygon
// covers its part of the stroke with windings of one sign); throws when out of range.
Path toPixels(const Polygon& polygon, const Affine2& user_to_pixels, const IntegerFrame& frame,
              double units_per_user) {
  constexpr double kMaxUnits = 4.0e18;  // as strokeArea: Clipper's hiRange
  Path path;
  for (const Point2& p : polygon) {
    const Point2 units = p * units_per_user;
    if (!units.allFinite() || units.cwiseAbs().maxCoeff() > kMaxUnits) {
      throw std::invalid_argument("stroke coordinates out of range");
    }
    const IntPoint q = frame.toInt(user_to_pixels * p);
    if (path.empty() || q != path.back()) path.push_back(q);
  }
  if (!ClipperLib::Orientation(path)) ClipperLib::ReversePath(path);
  return path;
}

// Pieces meet along shared edges (centreline, cap chords, the sides of join wedges), which
// Clipper's union does not always merge (a cap stayed a polygon of its own, its chord a
// boundary): closing by two integer units (1e-4 px at 256 px) joins them.
Paths merged(const Paths& area) {
  constexpr double kUnits = 2.0;
  constexpr double kMiterLimit = 64.0;  // corners stay where they are
  return offsetInSteps(area, {kUnits, -kUnits}, kMiterLimit);
}

}  // namespace

Paths curveStrokeArea(const std::vector<Subpath>& subpaths, const Affine2& user_to_pixels,
                      const StrokeGeometry& stroke, const IntegerFrame& frame, double tolerance,
                      VertexBudget& budget) {
  // Dashes are cut from the flattened path (dashPolyline): Clipper's way, not curves.
  if (!stroke.dashes.empty()) {
    return strokeArea(subpaths, user_to_pixels, stroke, frame, tolerance, budget);
  }
  if (!(stroke.width > 0.0)) return {};
  const double pixels_per_user = std::sqrt(std::abs(user_to_pixels.linear().determinant()));
  if (!(pixels_per_user > 0.0) || !std::isfinite(pixels_per_user)) return {};
  const double units_per_user = frame.unitsPerPixel() * pixels_per_user;
  // Fit and flattening share the tolerance, so that the outline is within it in total.
  const double user_tolerance = tolerance / pixels_per_user;
  const Tolerances tol{0.5 * user_tolerance, 0.5 * user_tolerance,
                       std::max(user_tolerance, 0.05 * stroke.width)};
  std::vector<Polygon> polygons;
  for (const Subpath& subpath : subpaths) strokeSubpath(subpath, stroke, tol, budget, polygons);
  Paths pixel_area;
  std::size_t vertices = 0;
  for (const Polygon& polygon : polygons) {
    checkShapeVertices(vertices += polygon.size());
    Path path = toPixels(polygon, user_to_pixels, frame, units_per_user);
    if (path.size() >= 3) pixel_area.push_back(std::move(path));
  }
  return merged(simplified(pixel_area, FillRule::kNonZero));
}

}  // namespace io_detail
}  // namespace vicc_glyphs
