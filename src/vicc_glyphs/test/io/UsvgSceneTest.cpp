// small-usvg SceneXML reader: the vendored ladybug (data/samples/ladybug_usvg.xml, MIT, see
// data/samples/README.md) read, dispatched and rendered, plus malformed input.
//
// Probe points (image pixels of the 1024 x 1024 scene) come from the file's curve 4, a closed
// spot on the shell spanning x 676..695, y 457..497, whose file-left colours are dark
// (71,24,8 ...) and file-right colours red (229,70,12 ...): a ladybug's spots are black on a red
// shell. The spot is traversed up its left edge (tangent (0,-1) at its first point (676.25,
// 474.25)), so its inside lies on the (-dy, dx) side: the file's left is our right. Reading the
// sides the other way round makes the spot red and the shell around it dark; swapping R and B
// makes the shell blue; either fails RendersARedShellWithADarkSpot.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "text_file.hpp"
#include "vicc_glyphs/io/load.hpp"
#include "vicc_glyphs/io/orzan_xml.hpp"
#include "vicc_glyphs/io/usvg_scene_xml.hpp"
#include "vicc_glyphs/render/renderer.hpp"

namespace vicc_glyphs {
namespace {

const std::string kLadybug = std::string(VICC_GLYPHS_DATA_DIR) + "/samples/ladybug_usvg.xml";

Color bytes(double r, double g, double b) { return Color(r, g, b) / 255.0; }

TEST(UsvgScene, ReadsTheVendoredLadybug) {
  const DiffusionCurveImage image = readUsvgSceneXml(kLadybug);
  EXPECT_EQ(image.width, 1024);
  EXPECT_EQ(image.height, 1024);
  ASSERT_EQ(image.curves.size(), 59u);  // <poisson_curve_set> and <mesh_set> are skipped

  // Curve 4 (the spot): coordinates as they are, sides exchanged, RGB order kept.
  const DiffusionCurve& spot = image.curves[3];
  ASSERT_EQ(spot.control_points.size(), 13u);
  EXPECT_EQ(spot.control_points.front(), Point2(676.25, 474.25));
  EXPECT_TRUE(spot.left_colors.front().rgb.isApprox(bytes(229, 70, 12)));
  EXPECT_TRUE(spot.right_colors.front().rgb.isApprox(bytes(71, 24, 8)));
  // globalID 40 is the largest of the set: the end of the curve (K = 4).
  EXPECT_DOUBLE_EQ(spot.left_colors.back().position, 4.0);
  EXPECT_DOUBLE_EQ(spot.right_colors[1].position, 4.0 * 7.0 / 40.0);

  // Curve 1: boundary="Neumann" on the file's right set makes our left side a barrier.
  EXPECT_FALSE(image.curves[0].left_emits);
  EXPECT_TRUE(image.curves[0].right_emits);

  // Curve 55 declares nb_right_colors="5" but lists 6: the first 5 are read (as small-usvg
  // does), globalIDs 2..68 normalised by 68 onto s in [0, 10].
  const DiffusionCurve& leaf = image.curves[54];
  ASSERT_EQ(leaf.left_colors.size(), 5u);
  EXPECT_DOUBLE_EQ(leaf.left_colors.front().position, 10.0 * 2.0 / 68.0);
  EXPECT_DOUBLE_EQ(leaf.left_colors.back().position, 10.0);
}

TEST(UsvgScene, LoadDispatchesXmlOnTheRootElement) {
  EXPECT_EQ(loadDiffusionCurves(kLadybug).curves.size(), 59u);
  const std::string orzan = std::string(VICC_GLYPHS_DATA_DIR) + "/samples/two_curves.xml";
  EXPECT_EQ(loadDiffusionCurves(orzan).curves.size(), readOrzanXml(orzan).curves.size());
  EXPECT_EQ(loadDiffusionCurves(kLadybug, 512).width, 512);
}

TEST(UsvgScene, RecognisesTheSceneRoot) {
  EXPECT_TRUE(hasUsvgSceneRoot("<!DOCTYPE SceneXML>\n<scene image_width=\"1\"/>"));
  EXPECT_TRUE(hasUsvgSceneRoot("<?xml version=\"1.0\"?><!-- <curve_set> --><scene>"));
  EXPECT_FALSE(hasUsvgSceneRoot("<!DOCTYPE CurveSetXML>\n<curve_set image_width=\"1\">"));
  EXPECT_FALSE(hasUsvgSceneRoot("<scenery/>"));
  EXPECT_FALSE(hasUsvgSceneRoot("<!-- unterminated"));
  EXPECT_FALSE(hasUsvgSceneRoot(""));
}

cv::Vec3f at(const cv::Mat& image, int x, int y) { return image.at<cv::Vec3f>(y, x); }

void expectDark(const cv::Vec3f& rgb, const std::string& where) {
  for (int c = 0; c < 3; ++c) EXPECT_LT(rgb[c], 0.35f) << where << " channel " << c;
}

void expectRed(const cv::Vec3f& rgb, const std::string& where) {
  EXPECT_GT(rgb[0], 0.6f) << where;
  EXPECT_GT(rgb[0], rgb[1] + 0.35f) << where;
  EXPECT_GT(rgb[0], rgb[2] + 0.35f) << where;
}

TEST(UsvgScene, RendersARedShellWithADarkSpot) {
  const DiffusionCurveImage image = readUsvgSceneXml(kLadybug);
  const RenderResult result = renderDiffusionCurves(image);
  ASSERT_EQ(result.image.size(), cv::Size(1024, 1024));
  expectDark(at(result.image, 686, 476), "inside the spot (curve 4), ~10 px from its outline");
  expectRed(at(result.image, 668, 474), "shell, 8 px left of the spot's leftmost point");
  expectRed(at(result.image, 680, 420), "shell, right of the upper spots");
}

// --- malformed input -------------------------------------------------------------------------

const std::string kFourPoints =
    "<control_point x=\"0\" y=\"0\"/><control_point x=\"1\" y=\"1\"/>"
    "<control_point x=\"2\" y=\"1\"/><control_point x=\"3\" y=\"0\"/>";
const std::string kColourSets =
    "<left_colors_set><left_color R=\"0\" G=\"0\" B=\"0\" globalID=\"0\"/></left_colors_set>"
    "<right_colors_set><right_color r=\"1\" g=\"0\" b=\"0\" globalID=\"0\"/></right_colors_set>";

std::string scene(const std::string& curve_body, const std::string& curve_attributes = "") {
  return "<!DOCTYPE SceneXML>\n<scene image_width=\"10\" image_height=\"10\"><curve_set>"
         "<curve" +
         curve_attributes + ">" + curve_body + "</curve></curve_set></scene>";
}

std::string withPoints(const std::string& points) {
  return scene("<control_points_set>" + points + "</control_points_set>" + kColourSets);
}

std::string errorOf(const std::string& text) {
  try {
    parseUsvgSceneXml(text);
  } catch (const FormatError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no FormatError for: " << text.substr(0, 200);
  return {};
}

void expectError(const std::string& text, const std::string& part) {
  const std::string message = errorOf(text);
  EXPECT_NE(message.find(part), std::string::npos) << message;
}

TEST(MalformedUsvgScene, ValidBaselineParses) {
  const DiffusionCurveImage image = parseUsvgSceneXml(withPoints(kFourPoints));
  ASSERT_EQ(image.curves.size(), 1u);
  // Lowercase channels are already in [0, 1]; the file's right set is our left.
  EXPECT_TRUE(image.curves[0].left_colors[0].rgb.isApprox(Color(1, 0, 0)));
}

TEST(MalformedUsvgScene, Truncated) {
  expectError(withPoints(kFourPoints).substr(0, 120), "malformed XML");
  const std::string ladybug = io_detail::readTextFile(kLadybug);
  expectError(ladybug.substr(0, ladybug.size() / 2), "malformed XML");
}

TEST(MalformedUsvgScene, NanAndInfinity) {
  expectError(withPoints("<control_point x=\"nan\" y=\"0\"/><control_point x=\"1\" y=\"1\"/>"
                         "<control_point x=\"2\" y=\"1\"/><control_point x=\"3\" y=\"0\"/>"),
              "curve 0 control point 0");
  expectError(scene("<control_points_set>" + kFourPoints +
                    "</control_points_set><left_colors_set><left_color R=\"inf\" G=\"0\" "
                    "B=\"0\" globalID=\"0\"/></left_colors_set>" +
                    "<right_colors_set><right_color R=\"0\" G=\"0\" B=\"0\" globalID=\"nan\"/>"
                    "</right_colors_set>"),
              "finite");
}

TEST(MalformedUsvgScene, MissingAttributesAndElements) {
  expectError(withPoints("<control_point y=\"0\"/><control_point x=\"1\" y=\"1\"/>"
                         "<control_point x=\"2\" y=\"1\"/><control_point x=\"3\" y=\"0\"/>"),
              "missing attribute x");
  expectError("<scene image_height=\"10\"/>", "missing attribute image_width");
  expectError(scene("<control_points_set>" + kFourPoints + "</control_points_set>"),
              "missing <left_colors_set>");
  expectError(scene("<control_points_set>" + kFourPoints +
                    "</control_points_set><left_colors_set/><right_colors_set/>"),
              "no <left_color>");
  expectError(scene("<control_points_set>" + kFourPoints +
                    "</control_points_set><left_colors_set><left_color G=\"0\" B=\"0\" "
                    "globalID=\"0\"/></left_colors_set>" +
                    "<right_colors_set><right_color R=\"0\" G=\"0\" B=\"0\" globalID=\"0\"/>"
                    "</right_colors_set>"),
              "missing attribute r");
}

TEST(MalformedUsvgScene, BadValues) {
  expectError("<curve_set image_width=\"10\" image_height=\"10\"/>", "expected a <scene>");
  expectError("<scene image_width=\"0\" image_height=\"10\"/>", "image size");
  expectError(withPoints(kFourPoints.substr(0, kFourPoints.size() / 2)), "3K+1");
  const std::string same = "<control_point x=\"2\" y=\"2\"/>";
  expectError(withPoints(same + same + same + same), "zero-length");
  expectError(scene("<control_points_set>" + kFourPoints + "</control_points_set>" +
                    "<left_colors_set><left_color R=\"300\" G=\"0\" B=\"0\" globalID=\"0\"/>"
                    "</left_colors_set><right_colors_set><right_color R=\"0\" G=\"0\" B=\"0\" "
                    "globalID=\"-1\"/></right_colors_set>"),
              "outside 0..255");
  // A declared count larger than what is there means the file was cut.
  expectError(scene("<control_points_set>" + kFourPoints + "</control_points_set>" + kColourSets,
                    " nb_control_points=\"7\""),
              "nb_control_points=7 but 4");
}

TEST(MalformedUsvgScene, TooManyControlPointsIsRejectedBeforeParsing) {
  std::string points;
  for (std::size_t i = 0; i <= kMaxControlPointsPerFile; ++i) {
    points += "<control_point x=\"1\" y=\"2\"/>";
  }
  expectError(withPoints(points), "limit per file");
}

}  // namespace
}  // namespace vicc_glyphs
