// Strokes outlined by own offset curves (curve_stroke.cpp) against the expected geometry and
// against Clipper's offsetting (svg_stroke.cpp). The accuracy table of
// bench/fidelity/README.md (session 18) is printed by vicc_glyphs_stroke_bench.

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

#include <gtest/gtest.h>

#include "curve_stroke.hpp"
#include "stroke/stroke_accuracy.hpp"
#include "vicc_glyphs/io/svg_import.hpp"

namespace vicc_glyphs {
namespace io_detail {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTolerance = stroke_accuracy::kTolerance;  // the importer's, in pixels

using Outliner =
    std::function<Paths(const std::vector<Subpath>&, const Affine2&, const StrokeGeometry&,
                        const IntegerFrame&, double, VertexBudget&)>;

const IntegerFrame& frame() { return stroke_accuracy::caseFrame(); }

Paths outline(const Outliner& outliner, const std::vector<Subpath>& subpaths,
              const StrokeGeometry& stroke, const Affine2& transform = Affine2::Identity()) {
  VertexBudget budget(1000000);
  return outliner(subpaths, transform, stroke, frame(), kTolerance, budget);
}
Paths curves(const std::vector<Subpath>& s, const StrokeGeometry& g) {
  return outline(curveStrokeArea, s, g);
}
Paths clipper(const std::vector<Subpath>& s, const StrokeGeometry& g) {
  return outline(strokeArea, s, g);
}

StrokeGeometry geometry(double width, LineCap cap, LineJoin join, double miter_limit = 4.0) {
  StrokeGeometry g;
  g.width = width;
  g.cap = cap;
  g.join = join;
  g.miter_limit = miter_limit;
  return g;
}

Subpath cubic(Point2 a, Point2 b, Point2 c, Point2 d) {
  return stroke_accuracy::cubicSubpath(a, b, c, d);
}

Subpath polyline(const std::vector<Point2>& points, bool closed = false) {
  Subpath s{{points.front()}, closed};
  for (std::size_t i = 1; i < points.size(); ++i) {
    const Point2 a = points[i - 1], b = points[i];
    s.points.insert(s.points.end(), {a + (b - a) / 3.0, a + 2.0 * (b - a) / 3.0, b});
  }
  return s;
}

Subpath circle(const Point2& c, double r) { return stroke_accuracy::circleSubpath(c, r); }

double areaOf(const Paths& paths) {
  double area = 0.0;
  for (const Path& p : paths) area += ClipperLib::Area(p);
  return area / (frame().unitsPerPixel() * frame().unitsPerPixel());
}

double iou(const Paths& a, const Paths& b) { return areaOf(intersect(a, b)) / areaOf(unite(a, b)); }

double minY(const Paths& paths) {
  double y = 1e300;
  for (const Path& p : paths)
    for (const IntPoint& q : p) y = std::min(y, frame().toPixel(q).y());
  return y;
}

TEST(CurveStroke, LineCapsGiveTheExpectedArea) {
  const std::vector<Subpath> line = {polyline({Point2(50, 100), Point2(150, 100)})};
  const double butt = 100.0 * 20.0;
  EXPECT_NEAR(areaOf(curves(line, geometry(20, LineCap::kButt, LineJoin::kMiter))), butt, 0.01);
  EXPECT_NEAR(areaOf(curves(line, geometry(20, LineCap::kSquare, LineJoin::kMiter))),
              butt + 2.0 * 10.0 * 20.0, 0.01);
  // Round: the flattened half discs lie inside the true ones by at most the tolerance.
  const double round = areaOf(curves(line, geometry(20, LineCap::kRound, LineJoin::kMiter)));
  EXPECT_LE(round, butt + kPi * 100.0 + 0.01);
  EXPECT_GE(round, butt + kPi * 100.0 - 2.0 * kPi * 10.0 * kTolerance);
}

TEST(CurveStroke, StrokedCircleIsAnAnnulus) {
  const Paths area =
      curves({circle(Point2(128, 128), 60)}, geometry(10, LineCap::kButt, LineJoin::kMiter));
  ASSERT_EQ(area.size(), 2u);  // the outer boundary and the hole
  std::vector<double> radii_min, radii_max;
  for (const Path& p : area) {
    double lo = 1e300, hi = 0.0;
    for (const IntPoint& q : p) {
      const double r = (frame().toPixel(q) - Point2(128, 128)).norm();
      lo = std::min(lo, r), hi = std::max(hi, r);
    }
    radii_min.push_back(lo), radii_max.push_back(hi);
  }
  const std::size_t outer = radii_max[0] > radii_max[1] ? 0 : 1;
  // The 4-cubic circle itself deviates by up to 2.7e-4 r (0.016 px) from the true one.
  const double allowed = 0.017 + kTolerance;
  EXPECT_NEAR(radii_min[outer], 65.0, allowed);
  EXPECT_NEAR(radii_max[outer], 65.0, allowed);
  EXPECT_NEAR(radii_min[1 - outer], 55.0, allowed);
  EXPECT_NEAR(radii_max[1 - outer], 55.0, allowed);
  EXPECT_NEAR(areaOf(area), kPi * (65.0 * 65.0 - 55.0 * 55.0), 3.0);
}

TEST(CurveStroke, MiterBeyondTheLimitBecomesABevel) {
  // Apex (128, 50), legs 78 x 150: miter ratio 1 / sin(half the angle) = 169.07 / 78 = 2.167.
  const std::vector<Subpath> wedge = {
      polyline({Point2(50, 200), Point2(128, 50), Point2(206, 200)})};
  const double half = 10.0, ratio = std::hypot(78.0, 150.0) / 78.0;
  const Paths miter = curves(wedge, geometry(2 * half, LineCap::kButt, LineJoin::kMiter, 2.5));
  EXPECT_NEAR(minY(miter), 50.0 - half * ratio, 0.01);
  // Limit 2 < 2.167: SVG bevels, the corner is cut at the two offset points.
  const Paths bevel = curves(wedge, geometry(2 * half, LineCap::kButt, LineJoin::kMiter, 2.0));
  EXPECT_NEAR(minY(bevel), 50.0 - half * 78.0 / std::hypot(78.0, 150.0), 0.01);
  const Paths explicit_bevel = curves(wedge, geometry(2 * half, LineCap::kButt, LineJoin::kBevel));
  EXPECT_NEAR(areaOf(bevel), areaOf(explicit_bevel), 1e-3);
  // The miter adds the triangle beyond the bevel: base 2 h cos, height h (ratio - sin).
  const double sin_half = 78.0 / std::hypot(78.0, 150.0),
               cos_half = 150.0 / std::hypot(78.0, 150.0);
  EXPECT_NEAR(areaOf(miter) - areaOf(bevel), half * cos_half * half * (ratio - sin_half), 0.05);
}

TEST(CurveStroke, CuspAndUTurnLeaveNoHoleOrFlood) {
  const StrokeGeometry round = geometry(20, LineCap::kRound, LineJoin::kRound);
  // Exact cusp on a line (the cubic runs to x = 172 and back): a round join at the turn.
  const std::vector<Subpath> back = {
      cubic(Point2(40, 128), Point2(216, 128), Point2(216, 128), Point2(40, 128))};
  const Paths cusp = curves(back, round);
  ASSERT_EQ(cusp.size(), 1u);
  EXPECT_NEAR(areaOf(cusp), 132.0 * 20.0 + kPi * 100.0, 0.5);
  EXPECT_NEAR(areaOf(cusp), areaOf(clipper(back, round)), 0.5);
  // Sharp U-turns whose radius of curvature at the tip is far below the half width: the inner
  // offset folds back over the stroke; the union must neither cancel it (hole) nor spill.
  for (const double gap : {16.0, 4.0, 0.5}) {
    const std::vector<Subpath> u = {
        cubic(Point2(40, 120), Point2(230, 120), Point2(230, 120 + gap), Point2(40, 120 + gap))};
    const Paths ours = curves(u, round), theirs = clipper(u, round);
    ASSERT_EQ(ours.size(), 1u) << "gap " << gap;  // one outline, no hole
    EXPECT_GT(ClipperLib::Area(ours[0]), 0.0);
    EXPECT_NEAR(areaOf(ours) / areaOf(theirs), 1.0, 0.002) << "gap " << gap;
    EXPECT_GE(iou(ours, theirs), 0.998) << "gap " << gap;
  }
  // The classic cusp cubic (0,0) (1,1) (0,1) (1,0), scaled.
  const std::vector<Subpath> classic = {
      cubic(Point2(40, 200), Point2(216, 24), Point2(40, 24), Point2(216, 200))};
  EXPECT_GE(iou(curves(classic, round), clipper(classic, round)), 0.998);
}

TEST(CurveStroke, AgreesWithClipperOnCurvyStrokes) {
  const std::vector<std::vector<Subpath>> cases = {
      {cubic(Point2(40, 128), Point2(120, 0), Point2(136, 256), Point2(216, 128))},
      {cubic(Point2(50, 200), Point2(250, 40), Point2(6, 40), Point2(206, 200))},  // loop
      {cubic(Point2(30, 60), Point2(120, 60), Point2(60, 200), Point2(200, 200)),
       cubic(Point2(200, 40), Point2(150, 90), Point2(250, 120), Point2(200, 160))},
      {circle(Point2(100, 120), 30), polyline({Point2(20, 20), Point2(230, 40), Point2(60, 240)})},
  };
  const std::vector<StrokeGeometry> strokes = {
      geometry(12, LineCap::kRound, LineJoin::kRound),
      geometry(30, LineCap::kButt, LineJoin::kBevel),
      geometry(8, LineCap::kSquare, LineJoin::kMiter, 10.0),
  };
  for (std::size_t c = 0; c < cases.size(); ++c) {
    for (std::size_t s = 0; s < strokes.size(); ++s) {
      EXPECT_GE(iou(curves(cases[c], strokes[s]), clipper(cases[c], strokes[s])), 0.99)
          << "case " << c << " stroke " << s;
    }
  }
  // A non-uniform transform stretches the stroke (an ellipse ring 2:1).
  const StrokeGeometry ring = geometry(6, LineCap::kButt, LineJoin::kRound);
  Affine2 stretch = Affine2::Identity();
  stretch.scale(Eigen::Vector2d(2.0, 1.0));
  const std::vector<Subpath> c = {circle(Point2(64, 128), 50)};
  const Paths ours = outline(curveStrokeArea, c, ring, stretch);
  EXPECT_GE(iou(ours, outline(strokeArea, c, ring, stretch)), 0.99);
  EXPECT_NEAR(areaOf(ours), kPi * 2.0 * (53.0 * 53.0 - 47.0 * 47.0), 10.0);
  // A mirroring transform reverses every piece; the orientation is normalised per piece.
  Affine2 mirror = Affine2::Identity();
  mirror.translate(Eigen::Vector2d(256.0, 0.0)).scale(Eigen::Vector2d(-1.0, 1.0));
  const std::vector<Subpath> s = cases[0];
  const Paths mirrored = outline(curveStrokeArea, s, ring, mirror);
  EXPECT_NEAR(areaOf(mirrored), areaOf(curves(s, ring)), 0.01);
  EXPECT_GE(iou(mirrored, outline(strokeArea, s, ring, mirror)), 0.99);
}

TEST(CurveStroke, DashedStrokesUseClipper) {
  StrokeGeometry dashed = geometry(6, LineCap::kRound, LineJoin::kRound);
  dashed.dashes = {10, 5};
  const std::vector<Subpath> s = {
      cubic(Point2(40, 128), Point2(120, 0), Point2(136, 256), Point2(216, 128))};
  EXPECT_EQ(curves(s, dashed), clipper(s, dashed));
}

TEST(CurveStroke, RefusesOutOfRangeAndTooManyVertices) {
  const StrokeGeometry g = geometry(2, LineCap::kRound, LineJoin::kRound);
  EXPECT_THROW(curves({polyline({Point2(0, 0), Point2(1e300, 0)})}, g), std::invalid_argument);
  VertexBudget small(100);
  EXPECT_THROW(curveStrokeArea({circle(Point2(128, 128), 100)}, Affine2::Identity(), g, frame(),
                               kTolerance, small),
               std::length_error);
  EXPECT_TRUE(curves({polyline({Point2(0, 0), Point2(9, 9)})},
                     geometry(0, LineCap::kButt, LineJoin::kMiter))
                  .empty());
}

TEST(CurveStroke, RandomChainsAgreeWithClipperWithRoundCapsAndJoins) {
  // Round caps and joins: both outliners approximate the same disc union, so their symmetric
  // difference per unit of outline length (area / (2 area / width)) stays at the tolerance.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> position(20, 236), width(1, 40), unit(0, 1);
  double worst = 0.0;
  for (int n = 0; n < 300; ++n) {
    Subpath s{{Point2(position(rng), position(rng))}, false};
    const int segments = 1 + static_cast<int>(unit(rng) * 3);
    for (int i = 0; i < 3 * segments; ++i) s.points.emplace_back(position(rng), position(rng));
    if (unit(rng) < 0.2) s.points[2] = s.points[1];  // coincident control points
    const StrokeGeometry g = geometry(width(rng), LineCap::kRound, LineJoin::kRound);
    const Paths ours = curves({s}, g), theirs = clipper({s}, g);
    const double difference = areaOf(subtract(ours, theirs)) + areaOf(subtract(theirs, ours));
    worst = std::max(worst, difference / (2.0 * areaOf(theirs) / g.width));
  }
  EXPECT_LE(worst, 0.02);  // pixels; ~0.006 over 1500 such chains
}

TEST(CurveStroke, ClosedPathRunningBackKeepsBothRoundEnds) {
  // A closed subpath out and back along a line (A, B, B, A reaches 3/4 of the way to B): a
  // capsule with round joins at both ends. Clipper's closed-line offsetting loses one of
  // them (976.5 px^2 instead of 1024.3).
  const Point2 a(49.7, 37.2), b(135.5, 112.4);
  const std::vector<Subpath> back = {{{a, b, b, a}, true}};
  const double half = 5.44, length = 0.75 * (b - a).norm();
  EXPECT_NEAR(areaOf(curves(back, geometry(2 * half, LineCap::kButt, LineJoin::kRound))),
              length * 2 * half + kPi * half * half, 0.5);
}

// Every outline vertex of a round-capped, round-joined stroke within the importer's tolerance
// of width / 2 from the centreline, with either outliner (the bench
// vicc_glyphs_stroke_bench prints the deviations, vertex counts and times).
TEST(CurveStroke, OffsetAccuracyAgainstTheTrueOffset) {
  for (const stroke_accuracy::AccuracyCase& c : stroke_accuracy::accuracyCases()) {
    const StrokeGeometry g = stroke_accuracy::roundStroke(c.width);
    for (const bool own : {false, true}) {
      const Paths area = own ? curves(c.subpaths, g) : clipper(c.subpaths, g);
      const stroke_accuracy::Deviation d =
          stroke_accuracy::deviation(area, frame(), c.subpaths, 0.5 * c.width);
      EXPECT_GT(d.vertices, 100u) << c.name;
      EXPECT_LE(d.max, kTolerance) << c.name << (own ? " curves" : " clipper");
    }
  }
}

TEST(CurveStroke, ImportOptionSwitchesTheOutliner) {
  const std::string svg =
      "<svg xmlns='http://www.w3.org/2000/svg' viewBox='0 0 24 24'><path d='M4 18 C4 4 20 4 20 "
      "18' fill='none' stroke='black' stroke-width='2' stroke-linecap='round'/></svg>";
  SvgImportOptions options;
  options.size = 64;
  const DiffusionCurveImage clipper_image = parseSvg(svg, options);
  options.stroke_outliner = StrokeOutliner::kCurves;
  const DiffusionCurveImage curves_image = parseSvg(svg, options);
  ASSERT_EQ(clipper_image.curves.size(), 1u);
  ASSERT_EQ(curves_image.curves.size(), 1u);
}

}  // namespace
}  // namespace io_detail
}  // namespace vicc_glyphs
