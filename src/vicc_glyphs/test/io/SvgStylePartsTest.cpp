// The parts behind the painting model: CSS rule matching and cascade order, dash splitting,
// paint-map compositing.

#include <tinyxml2.h>

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "bezier_refit.hpp"
#include "paint_map.hpp"
#include "svg_css.hpp"
#include "svg_stroke.hpp"

namespace vicc_glyphs {
namespace io_detail {
namespace {

std::string valuesFor(const StyleSheet& sheet, const std::string& element_xml) {
  tinyxml2::XMLDocument document;
  document.Parse(element_xml.c_str());
  std::string joined;
  for (const CssDeclaration& d : sheet.matching(*document.RootElement())) {
    joined += d.name + "=" + d.value + ";";
  }
  return joined;
}

TEST(SvgStyleSheet, MatchesByTypeClassIdInSpecificityOrder) {
  StyleSheet sheet;
  std::vector<std::string> unsupported;
  sheet.parse(
      "/* icons */ #x { fill: blue } .a.b { fill: red } path { fill: green; stroke: none }"
      " * { opacity: .5 } rect, .c { fill: black !important }",
      [&](const std::string& f) { unsupported.push_back(f); });
  EXPECT_TRUE(unsupported.empty());
  EXPECT_EQ(valuesFor(sheet, "<path/>"), "opacity=.5;fill=green;stroke=none;");
  EXPECT_EQ(valuesFor(sheet, "<path class='b a' id='x'/>"),
            "opacity=.5;fill=green;stroke=none;fill=red;fill=blue;");
  EXPECT_EQ(valuesFor(sheet, "<circle class='a'/>"), "opacity=.5;");
  EXPECT_EQ(valuesFor(sheet, "<circle class='c'/>"), "opacity=.5;fill=black;");
}

TEST(SvgStyleSheet, ReportsWhatItCannotMatch) {
  StyleSheet sheet;
  std::vector<std::string> unsupported;
  sheet.parse("g > path { fill: red } a:hover { fill: blue } @media print { x { y: z } } .ok { }",
              [&](const std::string& f) { unsupported.push_back(f); });
  ASSERT_GE(unsupported.size(), 3u);
  EXPECT_EQ(unsupported[0], "CSS selector 'g > path'");
  EXPECT_EQ(unsupported[1], "CSS selector 'a:hover'");
  EXPECT_NE(unsupported[2].find("at-rule"), std::string::npos);
  EXPECT_THROW(sheet.parse("path { fill: red", [](const std::string&) {}), std::invalid_argument);
}

TEST(SvgDashes, SplitsAPolylineByThePatternAndOffset) {
  const std::vector<Point2> line = {Point2(0, 0), Point2(5, 0), Point2(10, 0)};
  const auto dashes = dashPolyline(line, {3, 1}, 0.0);
  ASSERT_EQ(dashes.size(), 3u);  // [0,3] [4,7] [8,10]
  EXPECT_NEAR(dashes[0].front().x(), 0, 1e-12);
  EXPECT_NEAR(dashes[0].back().x(), 3, 1e-12);
  EXPECT_NEAR(dashes[1].front().x(), 4, 1e-12);
  EXPECT_EQ(dashes[1].size(), 3u);  // keeps the vertex at 5
  EXPECT_NEAR(dashes[1].back().x(), 7, 1e-12);
  EXPECT_NEAR(dashes[2].front().x(), 8, 1e-12);
  EXPECT_NEAR(dashes[2].back().x(), 10, 1e-12);
  const auto shifted = dashPolyline(line, {3, 1}, 3.5);  // starts inside the gap
  ASSERT_FALSE(shifted.empty());
  EXPECT_NEAR(shifted[0].front().x(), 0.5, 1e-12);
}

TEST(SvgPaintMap, TranslucentPaintSplitsAndBlendsWhatLiesBelow) {
  const IntegerFrame frame(10, 10);
  const Paths canvas = {rectangle(frame, 0, 0, 10, 10)};
  PaintMap map;
  map.paint({rectangle(frame, 0, 0, 6, 10)}, Color(1, 0, 0), 1.0);
  map.paint({rectangle(frame, 4, 0, 10, 10)}, Color(0, 0, 1), 0.5);
  const ResolvedPicture picture = map.resolve(Color(1, 1, 1), canvas);
  ASSERT_EQ(picture.regions.size(), 3u);  // red, red under blue, blue over white
  std::vector<Color> colors;
  for (const ColorRegion& r : picture.regions) colors.push_back(r.color);
  auto has = [&](const Color& c) {
    return std::any_of(colors.begin(), colors.end(),
                       [&](const Color& x) { return (x - c).norm() < 1e-9; });
  };
  EXPECT_TRUE(has(Color(1, 0, 0)));
  EXPECT_TRUE(has(Color(0.5, 0, 0.5)));
  EXPECT_TRUE(has(Color(0.5, 0.5, 1)));
  EXPECT_TRUE(picture.background.area.empty());
}

// A flattened quarter circle of radius 100 (400 vertices) comes back as a few cubics that stay
// within the tolerance of every vertex and of the true circle.
TEST(SvgBezierRefit, FitsAFlattenedArcWithFewCubicsWithinTolerance) {
  std::vector<Point2> arc;
  for (int i = 0; i <= 400; ++i) {
    const double a = 0.5 * M_PI * i / 400.0;
    arc.push_back(Point2(100 * std::cos(a), 100 * std::sin(a)));
  }
  std::vector<Point2> control_points = {arc.front()};
  const int segments = fitCubics(arc, Point2(0, 1), Point2(1, 0), 0.01, control_points);
  EXPECT_GE(segments, 1);
  EXPECT_LE(segments, 4);
  ASSERT_EQ(control_points.size(), 3u * segments + 1);
  EXPECT_LT((control_points.back() - arc.back()).norm(), 1e-12);
  DiffusionCurve curve;
  curve.control_points = control_points;
  for (int k = 0; k <= 1000; ++k) {
    EXPECT_NEAR(curve.pointAt(segments * k / 1000.0).norm(), 100.0, 0.02) << k;
  }
  // A straight run stays one straight segment.
  std::vector<Point2> line = {Point2(0, 0), Point2(1, 0), Point2(2, 0), Point2(5, 0)};
  std::vector<Point2> straight = {line.front()};
  EXPECT_EQ(fitCubics(line, Point2(1, 0), Point2(-1, 0), 0.01, straight), 1);
  for (const Point2& q : straight) EXPECT_NEAR(q.y(), 0.0, 1e-12);
}

}  // namespace
}  // namespace io_detail
}  // namespace vicc_glyphs
