// Unit tests of the SVG importer's parts (internal headers from src/io).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "svg_arc.hpp"
#include "svg_color.hpp"
#include "svg_path_data.hpp"
#include "svg_transform.hpp"

namespace vicc_glyphs {
namespace io_detail {
namespace {

std::vector<Contour> parse(const std::string& d) {
  PointBudget budget(1000);
  return parseSvgPathData(d, budget);
}

TEST(SvgPathData, RelativeLinesAndImplicitClose) {
  const auto contours = parse("m 1 2 l 3 0 h 2 v 4 H 1 z");
  ASSERT_EQ(contours.size(), 1u);
  const Contour& c = contours[0];
  ASSERT_EQ(c.size(), 3u * 5u + 1u);  // z adds the line back to the start
  EXPECT_EQ(c[3], Point2(4, 2));
  EXPECT_EQ(c[6], Point2(6, 2));
  EXPECT_EQ(c[9], Point2(6, 6));
  EXPECT_EQ(c[12], Point2(1, 6));
  EXPECT_EQ(c[15], Point2(1, 2));
  // Lines are straight cubics with their inner points at thirds.
  EXPECT_LT((c[1] - Point2(2, 2)).norm(), 1e-12);
}

TEST(SvgPathData, UnclosedSubpathsAreClosedForFilling) {
  const auto contours = parse("M0 0 L 10 0 L 10 10 M 20 20 L 30 20 L 30 30");
  ASSERT_EQ(contours.size(), 2u);
  EXPECT_EQ(contours[0].back(), Point2(0, 0));
  EXPECT_EQ(contours[1].front(), Point2(20, 20));
  EXPECT_EQ(contours[1].back(), Point2(20, 20));
}

TEST(SvgPathData, SmoothCubicReflectsTheLastControlPoint) {
  const auto contours = parse("M0,0 C 0,10 10,10 10,0 S 20,-10 20,0 Z");
  ASSERT_EQ(contours.size(), 1u);
  EXPECT_EQ(contours[0][4], Point2(10, -10));  // 2 * (10,0) - (10,10)
}

TEST(SvgPathData, QuadraticsAreElevatedExactly) {
  const auto contours = parse("M0 0 Q 3 6 6 0 T 12 0 Z");
  ASSERT_EQ(contours.size(), 1u);
  const Contour& c = contours[0];
  EXPECT_LT((c[1] - Point2(2, 4)).norm(), 1e-12);
  EXPECT_LT((c[2] - Point2(4, 4)).norm(), 1e-12);
  // T reflects the quadratic control (3,6) about (6,0) to (9,-6).
  EXPECT_LT((c[4] - Point2(8, -4)).norm(), 1e-12);
}

TEST(SvgPathData, CompactNumbersAndArcFlags) {
  // "a1 1 0 00 2 0" packs flags; ".5.5" is two numbers.
  const auto contours = parse("M-1-1l.5.5a1 1 0 00 2 0z");
  ASSERT_EQ(contours.size(), 1u);
  EXPECT_LT((contours[0][3] - Point2(-0.5, -0.5)).norm(), 1e-12);
  EXPECT_LT((contours[0][9] - Point2(1.5, -0.5)).norm(), 1e-12);  // two quarter arcs
}

TEST(SvgPathData, UnknownCommandIsRejectedWithItsOffset) {
  try {
    parse("M 0 0 L 1 1 X 2 2");
    FAIL() << "expected an exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'X'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("offset"), std::string::npos) << e.what();
  }
}

TEST(SvgPathData, BudgetLimitsPoints) {
  PointBudget budget(10);
  EXPECT_THROW(parseSvgPathData("M0 0 L1 0 L1 1 L0 1 L 0 2 Z", budget), std::length_error);
}

TEST(SvgArc, HalfCircleEndsAndStaysOnTheCircle) {
  const auto points = arcToCubics(Point2(0, 0), 5, 5, 0, false, true, Point2(10, 0));
  ASSERT_EQ(points.size(), 6u);  // two quarter circles
  EXPECT_LT((points.back() - Point2(10, 0)).norm(), 1e-12);
  EXPECT_LT((points[2] - Point2(5, -5)).norm(), 1e-9);  // sweep=1 goes through y < 0 here
  const Point2 b[4] = {Point2(0, 0), points[0], points[1], points[2]};
  const Point2 mid = 0.125 * b[0] + 0.375 * b[1] + 0.375 * b[2] + 0.125 * b[3];
  EXPECT_NEAR((mid - Point2(5, 0)).norm(), 5.0, 1e-3);
}

TEST(SvgArc, TooSmallRadiiAreScaledUp) {
  const auto points = arcToCubics(Point2(0, 0), 1, 1, 0, false, true, Point2(10, 0));
  EXPECT_LT((points.back() - Point2(10, 0)).norm(), 1e-12);
  EXPECT_LT((points[2] - Point2(5, -5)).norm(), 1e-9);
}

TEST(SvgTransform, ListIsComposedLeftToRight) {
  const Affine2 t = parseSvgTransform("translate(10,0) scale(2)");
  EXPECT_LT((t * Point2(1, 1) - Point2(12, 2)).norm(), 1e-12);
  const Affine2 m = parseSvgTransform("matrix(1 2 3 4 5 6)");
  EXPECT_LT((m * Point2(1, 1) - Point2(9, 12)).norm(), 1e-12);
  const Affine2 r = parseSvgTransform("rotate(90 10 10)");
  EXPECT_LT((r * Point2(20, 10) - Point2(10, 20)).norm(), 1e-12);
}

TEST(SvgTransform, BadInputThrows) {
  EXPECT_THROW(parseSvgTransform("scale(0)"), std::invalid_argument);
  EXPECT_THROW(parseSvgTransform("wobble(1)"), std::invalid_argument);
  EXPECT_THROW(parseSvgTransform("translate(1"), std::invalid_argument);
  EXPECT_THROW(parseSvgTransform("matrix(1 2 3)"), std::invalid_argument);
}

TEST(SvgColor, Formats) {
  EXPECT_LT((*parseSvgPaint("#f80") - Color(1, 136 / 255.0, 0)).norm(), 1e-12);
  EXPECT_LT((*parseSvgPaint("#FF8000") - Color(1, 128 / 255.0, 0)).norm(), 1e-12);
  EXPECT_LT((*parseSvgPaint("rgb(255, 0, 51)") - Color(1, 0, 0.2)).norm(), 1e-12);
  EXPECT_LT((*parseSvgPaint("rgb(100%,50%,0%)") - Color(1, 0.5, 0)).norm(), 1e-12);
  EXPECT_LT((*parseSvgPaint(" Navy ") - Color(0, 0, 128 / 255.0)).norm(), 1e-12);
  EXPECT_FALSE(parseSvgPaint("none").has_value());
  EXPECT_THROW(parseSvgPaint("url(#gradient)"), std::invalid_argument);
  EXPECT_THROW(parseSvgPaint("#12345"), std::invalid_argument);
  EXPECT_THROW(parseSvgPaint("rgb(1,2)"), std::invalid_argument);
}

}  // namespace
}  // namespace io_detail
}  // namespace vicc_glyphs
