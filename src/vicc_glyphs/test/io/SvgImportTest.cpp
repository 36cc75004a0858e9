#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>

#include "curve_geometry.hpp"
#include "vicc_glyphs/io/svg_import.hpp"

namespace vicc_glyphs {
namespace {

using test::besideCurve;
using test::flattenAll;
using test::flattenCurve;
using test::winding;

const std::string kIcons = std::string(VICC_GLYPHS_DATA_DIR) + "/icons/";
const std::string kTestData = std::string(VICC_GLYPHS_TEST_DATA_DIR) + "/";

bool near(const Color& a, const Color& b) { return (a - b).norm() < 1e-9; }

class VendoredIcon : public ::testing::TestWithParam<std::string> {};

// Every curve is closed, black (the fill) on its left, white (the background) on its right,
// and the left really is inside the icon: a point just off the curve on the left lies inside
// the flattened outline (nonzero rule, the MDI default), a point on the right outside.
TEST_P(VendoredIcon, ClosedCurvesWithFillInsideAndBackgroundOutside) {
  const DiffusionCurveImage image = importSvg(kIcons + GetParam() + ".svg");
  EXPECT_EQ(image.width, 24);
  EXPECT_EQ(image.height, 24);
  ASSERT_FALSE(image.curves.empty());
  const auto outline = flattenAll(image);
  for (std::size_t i = 0; i < image.curves.size(); ++i) {
    const DiffusionCurve& c = image.curves[i];
    EXPECT_EQ(c.control_points.front(), c.control_points.back()) << "curve " << i;
    ASSERT_EQ(c.left_colors.size(), 2u) << "curve " << i;
    ASSERT_EQ(c.right_colors.size(), 2u) << "curve " << i;
    EXPECT_TRUE(near(c.left_colors[0].rgb, Color(0, 0, 0))) << "curve " << i;
    EXPECT_TRUE(near(c.right_colors[0].rgb, Color(1, 1, 1))) << "curve " << i;
    int checked = 0;
    for (int k = 0; k < c.segmentCount(); ++k) {
      const double s = k + 0.5;
      const double speed = c.derivativeAt(s).norm();
      if (speed < 1e-3) continue;
      // Close to the curve compared to the segment, so the point stays beside this segment.
      const double offset = std::min(0.01, 0.05 * speed);
      EXPECT_NE(winding(outline, besideCurve(c, s, offset)), 0) << "curve " << i << " s " << s;
      EXPECT_EQ(winding(outline, besideCurve(c, s, -offset)), 0) << "curve " << i << " s " << s;
      ++checked;
    }
    EXPECT_GT(checked, 0);
  }
}

INSTANTIATE_TEST_SUITE_P(MaterialDesignIcons, VendoredIcon,
                         ::testing::Values("weather-pouring", "virus", "brain", "heart", "lungs"));

// The import size scales the geometry: the curves at 240 px are those at 24 px times 10, up to
// the flattening of the curved parts (a small fraction of a pixel).
Eigen::AlignedBox2d boundsOf(const DiffusionCurveImage& image) {
  Eigen::AlignedBox2d box;
  for (const DiffusionCurve& c : image.curves) {
    for (const Point2& p : flattenCurve(c)) box.extend(p);
  }
  return box;
}

TEST(SvgImport, SizeScalesToRequestedWidth) {
  SvgImportOptions options;
  options.size = 240;
  const DiffusionCurveImage big = importSvg(kIcons + "heart.svg", options);
  const DiffusionCurveImage small = importSvg(kIcons + "heart.svg");
  EXPECT_EQ(big.width, 240);
  EXPECT_EQ(big.height, 240);
  ASSERT_EQ(big.curves.size(), small.curves.size());
  const Eigen::AlignedBox2d big_box = boundsOf(big);
  const Eigen::AlignedBox2d small_box = boundsOf(small);
  EXPECT_LT((big_box.min() - 10.0 * small_box.min()).norm(), 0.1);
  EXPECT_LT((big_box.max() - 10.0 * small_box.max()).norm(), 0.1);
  // The heart path's lowest point is its tip at y = 21.35.
  EXPECT_NEAR(small_box.max().y(), 21.35, 1e-3);
}

TEST(SvgImport, BackgroundOptionIsTheOutsideColour) {
  SvgImportOptions options;
  options.background = Color(0.2, 0.4, 0.6);
  const DiffusionCurveImage image = importSvg(kIcons + "heart.svg", options);
  EXPECT_TRUE(near(image.curves[0].right_colors[0].rgb, Color(0.2, 0.4, 0.6)));
}

// The hole's curve has the background towards the hole centre and the fill away from it.
void expectDonut(const std::string& file) {
  const DiffusionCurveImage image = importSvg(kTestData + file);
  ASSERT_EQ(image.curves.size(), 2u);
  const Color navy(0, 0, 128 / 255.0);
  const Point2 centre(20, 20);
  for (const DiffusionCurve& c : image.curves) {
    const double radius = (c.pointAt(0.5) - centre).norm();
    const Point2 left = besideCurve(c, 0.5, 0.5);
    const bool left_faces_centre = (left - centre).norm() < radius;
    const Color toward_centre = left_faces_centre ? c.left_colors[0].rgb : c.right_colors[0].rgb;
    const Color away = left_faces_centre ? c.right_colors[0].rgb : c.left_colors[0].rgb;
    if (radius > 12.0) {  // outer circle: fill inside, background outside
      EXPECT_TRUE(near(toward_centre, navy)) << file;
      EXPECT_TRUE(near(away, Color(1, 1, 1))) << file;
    } else {  // hole: background inside the hole
      EXPECT_NEAR(radius, 8.0, 1e-2);
      EXPECT_TRUE(near(toward_centre, Color(1, 1, 1))) << file;
      EXPECT_TRUE(near(away, navy)) << file;
    }
    // The fill is always on the left.
    EXPECT_TRUE(near(c.left_colors[0].rgb, navy)) << file;
  }
}

TEST(SvgImport, EvenOddDonutHasBackgroundInTheHole) { expectDonut("donut_evenodd.svg"); }
TEST(SvgImport, NonZeroDonutHasBackgroundInTheHole) { expectDonut("donut_nonzero.svg"); }

TEST(SvgImport, EvenOddRuleDecidesTheHoleNotTheDirection) {
  // The evenodd file's circles run the same way; with nonzero (the default used here) there is
  // no hole: the inner circle lies inside the fill and makes no curve.
  std::string text =
      "<svg xmlns='http://www.w3.org/2000/svg' viewBox='0 0 40 40'><path fill='#000080' "
      "d='M 20 4 A 16 16 0 1 1 20 36 A 16 16 0 1 1 20 4 Z M 20 12 A 8 8 0 1 1 20 28 A 8 8 0 1 1 "
      "20 12 Z'/></svg>";
  const DiffusionCurveImage image = parseSvg(text);
  ASSERT_EQ(image.curves.size(), 1u);
  const Color navy(0, 0, 128 / 255.0);
  EXPECT_TRUE(near(image.curves[0].left_colors[0].rgb, navy));
  EXPECT_TRUE(near(image.curves[0].right_colors[0].rgb, Color(1, 1, 1)));
}

// The curves with `left` on their left side.
std::vector<const DiffusionCurve*> curvesWithLeft(const DiffusionCurveImage& image,
                                                  const Color& left) {
  std::vector<const DiffusionCurve*> found;
  for (const DiffusionCurve& c : image.curves) {
    if (near(c.left_colors[0].rgb, left)) found.push_back(&c);
  }
  return found;
}

TEST(SvgImport, ColouredShapesGetTheirFillAndTheColourAround) {
  const DiffusionCurveImage image = importSvg(kTestData + "coloured_shapes.svg");
  EXPECT_EQ(image.width, 100);
  EXPECT_EQ(image.height, 80);
  // The red square, the disc, the triangle: the square's hole, which the disc fills, is the
  // disc's outline and makes no curve of its own; the fill="none" square adds nothing.
  ASSERT_EQ(image.curves.size(), 3u);
  const auto red = curvesWithLeft(image, Color(1, 0, 0));
  const auto blue = curvesWithLeft(image, Color(0, 0, 1));
  const auto green = curvesWithLeft(image, Color(0, 1, 0));
  ASSERT_EQ(red.size(), 1u);
  ASSERT_EQ(blue.size(), 1u);
  ASSERT_EQ(green.size(), 1u);
  // The blue disc lies on the red square: red is its outside colour.
  EXPECT_TRUE(near(blue[0]->right_colors[0].rgb, Color(1, 0, 0)));
  EXPECT_TRUE(near(green[0]->right_colors[0].rgb, Color(1, 1, 1)));
  // The group's translate(60 10) moved the triangle's first corner from (0,0).
  bool moved_corner = false;
  for (const Point2& p : green[0]->control_points)
    moved_corner |= (p - Point2(60, 10)).norm() < 1e-4;
  EXPECT_TRUE(moved_corner);
  for (std::size_t k = 0; k < blue[0]->control_points.size(); k += 3) {
    EXPECT_NEAR((blue[0]->control_points[k] - Point2(30, 30)).norm(), 10.0, 0.01);  // on the circle
  }
}

DiffusionCurveImage importedSquares(const std::string& shapes) {
  SvgImportOptions options;
  options.size = 64;
  return parseSvg(
      "<svg xmlns='http://www.w3.org/2000/svg' viewBox='0 0 20 20'>" + shapes + "</svg>", options);
}

// One curve per boundary: the hole a region leaves in another is not repeated when one
// region fills it (the inner outline carries both colours), and kept when several do.
TEST(SvgImport, AHoleFilledByOneRegionIsItsOutlineOnly) {
  const DiffusionCurveImage image = importedSquares(
      "<rect x='2' y='2' width='16' height='16' fill='#808080'/>"
      "<rect x='6' y='6' width='8' height='8' fill='#ff0000'/>");
  ASSERT_EQ(image.curves.size(), 2u);  // grey outline, red outline
  const Color grey = Color(0x80, 0x80, 0x80) / 255.0;
  const auto red = curvesWithLeft(image, Color(1, 0, 0));
  ASSERT_EQ(red.size(), 1u);
  EXPECT_LT((red[0]->leftColorAt(0.5) - Color(1, 0, 0)).norm(), 1e-3);
  EXPECT_LT((red[0]->rightColorAt(0.5) - grey).norm(), 1e-3);
  ASSERT_EQ(curvesWithLeft(image, grey).size(), 1u);
  EXPECT_LT((curvesWithLeft(image, grey)[0]->rightColorAt(0.5) - Color(1, 1, 1)).norm(), 1e-3);
}

TEST(SvgImport, AHoleWithSeveralColoursAcrossIsKept) {
  const DiffusionCurveImage image = importedSquares(
      "<rect x='2' y='2' width='16' height='16' fill='#808080'/>"
      "<rect x='6' y='6' width='4' height='8' fill='#ff0000'/>"
      "<rect x='10' y='6' width='4' height='8' fill='#0000ff'/>");
  ASSERT_EQ(image.curves.size(), 4u);  // grey outline and hole, red, blue
  ASSERT_EQ(curvesWithLeft(image, Color(0x80, 0x80, 0x80) / 255.0).size(), 2u);
}

TEST(SvgImport, TransformsNestAndApplyInOrder) {
  const std::string text =
      "<svg xmlns='http://www.w3.org/2000/svg' width='100' height='100'>"
      "<g transform='translate(50,50)'><g transform='rotate(90)'>"
      "<rect x='0' y='0' width='10' height='20' transform='scale(2 1)' fill='black'/>"
      "</g></g></svg>";
  const DiffusionCurveImage image = parseSvg(text);
  ASSERT_EQ(image.curves.size(), 1u);
  // Corner (20, 20) after scale -> rotate 90 degrees (x, y) -> (-y, x) -> translate.
  bool found = false;
  for (const Point2& p : image.curves[0].control_points)
    found |= (p - Point2(30, 70)).norm() < 1e-4;  // Clipper's integer grid
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace vicc_glyphs
