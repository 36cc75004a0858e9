#include <gtest/gtest.h>

#include <cstdio>

#include "vicc_glyphs/io/orzan_xml.hpp"

namespace vicc_glyphs {
namespace {

const std::string kSample = std::string(VICC_GLYPHS_DATA_DIR) + "/samples/two_curves.xml";

void expectColor(const ColorPoint& c, double s, int r, int g, int b) {
  EXPECT_DOUBLE_EQ(c.position, s);
  EXPECT_NEAR(c.rgb[0], r / 255.0, 1e-12);
  EXPECT_NEAR(c.rgb[1], g / 255.0, 1e-12);
  EXPECT_NEAR(c.rgb[2], b / 255.0, 1e-12);
}

TEST(OrzanXml, SampleHasSizeCurvesAndSwappedCoordinates) {
  const DiffusionCurveImage image = readOrzanXml(kSample);
  EXPECT_EQ(image.width, 64);
  EXPECT_EQ(image.height, 48);
  ASSERT_EQ(image.curves.size(), 2u);
  const DiffusionCurve& c = image.curves[0];
  ASSERT_EQ(c.control_points.size(), 7u);
  EXPECT_EQ(c.segmentCount(), 2);
  // <control_point x="10" y="8"/> is column 8, row 10.
  EXPECT_EQ(c.control_points[0], Point2(8, 10));
  EXPECT_EQ(c.control_points[6], Point2(56, 38));
  EXPECT_EQ(image.curves[1].control_points[3], Point2(62, 24));
}

TEST(OrzanXml, SampleColoursAreBgrAndSidesKept) {
  const DiffusionCurveImage image = readOrzanXml(kSample);
  const DiffusionCurve& c = image.curves[0];
  // The file's left set (G=128 R=255 B=0) is our left side, with B and R exchanged.
  ASSERT_EQ(c.left_colors.size(), 2u);
  expectColor(c.left_colors[0], 0.0, 0, 128, 255);
  expectColor(c.left_colors[1], 2.0, 200, 64, 32);
  ASSERT_EQ(c.right_colors.size(), 3u);
  expectColor(c.right_colors[1], 0.5, 0, 0, 0);
  expectColor(c.right_colors[2], 2.0, 30, 10, 20);
  ASSERT_EQ(c.blur_points.size(), 2u);
  EXPECT_DOUBLE_EQ(c.blur_points[1].position, 2.0);
  EXPECT_DOUBLE_EQ(c.blur_points[1].sigma, 2.0);
  const DiffusionCurve& barrier = image.curves[1];
  EXPECT_FALSE(barrier.left_emits);
  EXPECT_TRUE(barrier.right_emits);
  expectColor(barrier.right_colors.at(0), 1.0, 204, 51, 102);
}

DiffusionCurveImage makeImage() {
  DiffusionCurveImage image;
  image.width = 320;
  image.height = 200;
  DiffusionCurve a;
  a.control_points = {Point2(1.25, 2.5),    Point2(10.1, 3.3),     Point2(20.7, 40.9),
                      Point2(33, 44),       Point2(40.0001, 50.5), Point2(60.3, 70.7),
                      Point2(100.5, 150.25)};
  a.left_colors = {
      {0.0, Color(0.1, 0.2, 0.3)}, {1.37, Color(1.0, 0.0, 0.5)}, {2.0, Color(0, 0, 0)}};
  a.right_colors = {{0.5, Color(0.9, 0.8, 0.7)}};
  a.blur_points = {{0.0, 0.5}, {2.0, 3.25}};
  DiffusionCurve b;
  b.control_points = {Point2(0, 0), Point2(1, 1), Point2(2, 1), Point2(3, 0)};
  b.left_emits = false;
  b.right_colors = {{1.0, Color(0.25, 0.5, 0.75)}};
  image.curves = {a, b};
  return image;
}

void expectSameImage(const DiffusionCurveImage& expected, const DiffusionCurveImage& actual) {
  EXPECT_EQ(actual.width, expected.width);
  EXPECT_EQ(actual.height, expected.height);
  ASSERT_EQ(actual.curves.size(), expected.curves.size());
  for (std::size_t i = 0; i < expected.curves.size(); ++i) {
    const DiffusionCurve& e = expected.curves[i];
    const DiffusionCurve& a = actual.curves[i];
    ASSERT_EQ(a.control_points.size(), e.control_points.size());
    for (std::size_t j = 0; j < e.control_points.size(); ++j) {
      EXPECT_EQ(a.control_points[j], e.control_points[j]) << "curve " << i << " point " << j;
    }
    auto sameColors = [](const std::vector<ColorPoint>& x, const std::vector<ColorPoint>& y) {
      ASSERT_EQ(x.size(), y.size());
      for (std::size_t k = 0; k < x.size(); ++k) {
        EXPECT_NEAR(x[k].position, y[k].position, 1e-12);
        EXPECT_LT((x[k].rgb - y[k].rgb).norm(), 1e-12);
      }
    };
    sameColors(e.left_colors, a.left_colors);
    sameColors(e.right_colors, a.right_colors);
    ASSERT_EQ(a.blur_points.size(), e.blur_points.size());
    for (std::size_t k = 0; k < e.blur_points.size(); ++k) {
      EXPECT_NEAR(a.blur_points[k].position, e.blur_points[k].position, 1e-12);
      EXPECT_EQ(a.blur_points[k].sigma, e.blur_points[k].sigma);
    }
    EXPECT_EQ(a.left_emits, e.left_emits);
    EXPECT_EQ(a.right_emits, e.right_emits);
  }
}

TEST(OrzanXml, RoundTripThroughTextIsLossless) {
  const DiffusionCurveImage image = makeImage();
  expectSameImage(image, parseOrzanXml(formatOrzanXml(image)));
}

TEST(OrzanXml, RoundTripThroughFileIsLossless) {
  const DiffusionCurveImage image = makeImage();
  const std::string path = ::testing::TempDir() + "/vicc_orzan_round_trip.xml";
  writeOrzanXml(image, path);
  const DiffusionCurveImage first = readOrzanXml(path);
  expectSameImage(image, first);
  // A second cycle gives the identical text.
  EXPECT_EQ(formatOrzanXml(first), formatOrzanXml(image));
  std::remove(path.c_str());
}

TEST(OrzanXml, SampleSurvivesRoundTrip) {
  const DiffusionCurveImage image = readOrzanXml(kSample);
  expectSameImage(image, parseOrzanXml(formatOrzanXml(image)));
}

// An emitting side without colour points diffused black: the file is refused instead, naming
// the curve and the side; a barrier side (boundary="Neumann") needs none.
TEST(OrzanXml, AnEmittingSideWithoutColoursIsAFormatError) {
  const std::string curve_start =
      "<curve_set image_width=\"32\" image_height=\"32\"><curve><control_points_set>"
      "<control_point x=\"2\" y=\"2\"/><control_point x=\"10\" y=\"10\"/>"
      "<control_point x=\"20\" y=\"20\"/><control_point x=\"30\" y=\"30\"/>"
      "</control_points_set>"
      "<left_colors_set><left_color G=\"0\" R=\"255\" globalID=\"0\" B=\"0\"/>"
      "</left_colors_set>";
  try {
    parseOrzanXml(curve_start + "<right_colors_set></right_colors_set></curve></curve_set>");
    ADD_FAILURE() << "no error";
  } catch (const FormatError& e) {
    EXPECT_NE(std::string(e.what()).find("right_colors_set has no colour points"),
              std::string::npos)
        << e.what();
  }
  const DiffusionCurveImage barrier = parseOrzanXml(
      curve_start +
      "<right_colors_set boundary=\"Neumann\"></right_colors_set></curve></curve_set>");
  ASSERT_EQ(barrier.curves.size(), 1u);
  EXPECT_FALSE(barrier.curves[0].right_emits);
}

TEST(OrzanXml, WritingAnInvalidImageThrows) {
  DiffusionCurveImage image = makeImage();
  image.curves[0].control_points.pop_back();
  EXPECT_THROW(formatOrzanXml(image), FormatError);
}

}  // namespace
}  // namespace vicc_glyphs
