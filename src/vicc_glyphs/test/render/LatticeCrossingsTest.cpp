#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "sample_images.hpp"
#include "vicc_glyphs/render/grid_problem.hpp"
#include "vicc_glyphs/render/lattice_crossings.hpp"

namespace vicc_glyphs {
namespace {

std::vector<LatticeCrossing> crossingsOf(const DiffusionCurveImage& image, double scale = 1.0) {
  std::vector<LatticeCrossing> found;
  forEachLatticeCrossing(image, scale, image.width, image.height,
                         [&](const LatticeCrossing& c) { found.push_back(c); });
  return found;
}

TEST(LatticeCrossingsTest, RightwardLineHasItsLeftSideAbove) {
  DiffusionCurveImage image{20, 20, {}};
  image.curves.push_back(lineCurve({0, 10.2}, {20, 10.2}, Color(1, 0, 0), Color(0, 0, 1)));
  const std::vector<LatticeCrossing> crossings = crossingsOf(image);
  ASSERT_EQ(crossings.size(), 20u);  // one per column line x = i + 0.5
  for (const LatticeCrossing& c : crossings) {
    EXPECT_EQ(c.left_pixel.y, 9);  // y down: walking right, the left side is up on screen
    EXPECT_EQ(c.right_pixel.y, 10);
    EXPECT_EQ(c.left_pixel.x, c.right_pixel.x);
    EXPECT_NEAR(c.left_distance, 0.7, 1e-3);  // sample points snap to 1/1024 pixel
    EXPECT_NEAR(c.right_distance, 0.3, 1e-3);
    EXPECT_NEAR(c.left_link_distance, 0.7, 1e-3);  // across a vertical link: the same
    EXPECT_NEAR(c.right_link_distance, 0.3, 1e-3);
    EXPECT_NEAR(c.footprint, 0.5, 1e-12);
    EXPECT_NEAR(c.position, (c.left_pixel.x + 0.5) / 20.0, 1e-6);
  }
}

TEST(LatticeCrossingsTest, ScaleMapsTheCurveToTheGrid) {
  DiffusionCurveImage image{40, 40, {}};
  image.curves.push_back(lineCurve({0, 20.4}, {40, 20.4}, Color(1, 0, 0), Color(0, 0, 1)));
  std::vector<LatticeCrossing> crossings;
  forEachLatticeCrossing(image, 0.5, 20, 20,
                         [&](const LatticeCrossing& c) { crossings.push_back(c); });
  ASSERT_EQ(crossings.size(), 20u);
  EXPECT_EQ(crossings.front().left_pixel.y, 9);  // y = 10.2 on the half-size grid
}

TEST(LatticeCrossingsTest, DiagonalCrossesRowsAndColumns) {
  DiffusionCurveImage image{10, 10, {}};
  image.curves.push_back(lineCurve({0, 0}, {10, 10}, Color(1, 0, 0), Color(0, 0, 1)));
  const std::vector<LatticeCrossing> crossings = crossingsOf(image);
  EXPECT_EQ(crossings.size(), 20u);  // through every pixel centre: rows and columns once each
  for (const LatticeCrossing& c : crossings) EXPECT_NEAR(c.footprint, 0.7071, 1e-3);
}

TEST(LatticeCrossingsTest, EndsOutsideTheImageAreContinued) {
  // A 36 pixel image on the 3x3 grid of scale 1/16: the last row's centre line y = 2.5 lies
  // past the scaled image border 2.25. The curve leaves the image at full scale, but scaled
  // it would end at y = 2.375 and stop short of that line without the continuation.
  DiffusionCurveImage image{36, 36, {}};
  image.curves.push_back(lineCurve({10.2, 10}, {10.2, 38}, Color(1, 0, 0), Color(0, 0, 1)));
  std::vector<LatticeCrossing> crossings;
  forEachLatticeCrossing(image, 1.0 / 16.0, 3, 3,
                         [&](const LatticeCrossing& c) { crossings.push_back(c); });
  ASSERT_EQ(crossings.size(), 2u);
  EXPECT_EQ(crossings.back().left_pixel.y, 2);
  EXPECT_DOUBLE_EQ(crossings.back().position, 1.0);  // the end's colour
}

TEST(LatticeCrossingsTest, CurvesOutsideOrWithoutLengthGiveNone) {
  DiffusionCurveImage image{10, 10, {}};
  image.curves.push_back(lineCurve({50, 50}, {80, 90}, Color(1, 0, 0), Color(0, 0, 1)));
  image.curves.push_back(lineCurve({5, 5}, {5, 5}, Color(1, 0, 0), Color(0, 0, 1)));
  DiffusionCurve broken;
  broken.control_points = {{0, 0}, {10, 10}};  // not 3K+1 points
  image.curves.push_back(broken);
  EXPECT_TRUE(crossingsOf(image).empty());
}

// Crossings of the link between pixels (x, y) and (x + 1, y).
int crossingsOfRowLink(const std::vector<LatticeCrossing>& crossings, int x, int y) {
  int count = 0;
  for (const LatticeCrossing& c : crossings) {
    const GridPixel& a = c.left_pixel;
    const GridPixel& b = c.right_pixel;
    count += a.y == y && b.y == y && std::min(a.x, b.x) == x && std::max(a.x, b.x) == x + 1;
  }
  return count;
}

// A corner that comes up to the line of pixel centres y = 5.5 and turns back touches the link
// it meets there: no crossing (the half-open ranges would count the line at the end of the one
// side and the start of the next, in opposite directions, and give both pixels both colours).
// A corner on that line that the curve passes through crosses it once.
TEST(LatticeCrossingsTest, ACornerTouchingALineOfPixelCentresDoesNotCrossIt) {
  DiffusionCurveImage touch{12, 12, {}};
  touch.curves.push_back(
      polygonCurve({{8.1, 9.2}, {5.3, 5.5}, {2.2, 9.3}}, Color(1, 0, 0), Color(0, 0, 1)));
  EXPECT_EQ(crossingsOfRowLink(crossingsOf(touch), 4, 5), 0);
  const GridProblem problem = assembleColorProblem(touch, 12, 12, 1.0, Color::Zero());
  EXPECT_TRUE(problem.couples_right[5 * 12 + 4]);   // the touched link stays
  for (int p = 0; p < problem.pixelCount(); ++p) {  // every Dirichlet pixel red or blue
    if (!problem.fixed[p]) continue;
    EXPECT_TRUE(problem.value(1, p) == 0.0f && (problem.value(0, p) + problem.value(2, p)) == 1.0f)
        << p % 12 << ", " << p / 12;
  }

  DiffusionCurveImage through{12, 12, {}};
  through.curves.push_back(
      polygonCurve({{8.1, 3.2}, {5.3, 5.5}, {2.2, 9.3}}, Color(1, 0, 0), Color(0, 0, 1)));
  EXPECT_EQ(crossingsOfRowLink(crossingsOf(through), 4, 5), 1);
}

// A slanted curve through pixel centres (an icon's 45-degree edge on the lattice's diagonal)
// meets a row line and a column line at each of them. Moved by an infinitesimal (e, e^2), the
// lattice puts each centre on one side: its two crossings agree, and no Dirichlet pixel takes
// the mean of both colours (before, each centre on the line took red and blue at distance 0).
TEST(LatticeCrossingsTest, ASlantedCurveThroughPixelCentresPutsEachOnOneSide) {
  for (const Point2& to : {Point2(12.0, 12.0), Point2(0.0, 12.0)}) {  // down-right, down-left
    DiffusionCurveImage image{12, 12, {}};
    const Point2 from = to.x() > 0.0 ? Point2(0.0, 0.0) : Point2(12.0, 0.0);
    image.curves.push_back(lineCurve(from, to, Color(1, 0, 0), Color(0, 0, 1)));
    const GridProblem problem = assembleColorProblem(image, 12, 12, 1.0, Color::Zero());
    int centres = 0;
    for (int p = 0; p < problem.pixelCount(); ++p) {
      if (!problem.fixed[p]) continue;
      const float red = problem.value(0, p), blue = problem.value(2, p);
      EXPECT_TRUE((red == 1.0f && blue == 0.0f) || (red == 0.0f && blue == 1.0f))
          << p % 12 << ", " << p / 12 << ": " << red << " " << blue;
      const double x = p % 12 + 0.5, y = p / 12 + 0.5;
      centres += to.x() > 0.0 ? x == y : x == 12.0 - y;
    }
    EXPECT_GE(centres, 10);  // the centres on the line are Dirichlet pixels, one colour each
  }
}

}  // namespace
}  // namespace vicc_glyphs
