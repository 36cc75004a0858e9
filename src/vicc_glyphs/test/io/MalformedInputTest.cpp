// Bad input must give a FormatError with a message that says what and where, quickly.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <sstream>

#include "vicc_glyphs/io/load.hpp"
#include "vicc_glyphs/io/orzan_xml.hpp"
#include "vicc_glyphs/io/svg_import.hpp"

namespace vicc_glyphs {
namespace {

const std::string kCurveHead =
    "<!DOCTYPE CurveSetXML>\n<curve_set image_width=\"10\" image_height=\"10\">\n<curve>\n";
const std::string kColourSets =
    "<left_colors_set><left_color G=\"0\" R=\"0\" globalID=\"0\" B=\"0\"/></left_colors_set>"
    "<right_colors_set><right_color G=\"0\" R=\"0\" globalID=\"0\" B=\"0\"/></right_colors_set>";

std::string orzanWithPoints(const std::string& points) {
  return kCurveHead + "<control_points_set>" + points + "</control_points_set>" + kColourSets +
         "</curve></curve_set>";
}

std::string svgWithPath(const std::string& d) {
  return "<svg xmlns='http://www.w3.org/2000/svg' viewBox='0 0 10 10'><path d='" + d + "'/></svg>";
}

template <typename Parse>
std::string errorOf(Parse parse) {
  try {
    parse();
  } catch (const FormatError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no FormatError";
  return {};
}

bool mentions(const std::string& message, const std::string& part) {
  return message.find(part) != std::string::npos;
}

const std::string kFourPoints =
    "<control_point x=\"0\" y=\"0\"/><control_point x=\"1\" y=\"1\"/>"
    "<control_point x=\"2\" y=\"1\"/><control_point x=\"3\" y=\"0\"/>";

TEST(MalformedOrzan, ValidBaselineParses) {
  EXPECT_EQ(parseOrzanXml(orzanWithPoints(kFourPoints)).curves.size(), 1u);
}

TEST(MalformedOrzan, TruncatedXml) {
  const std::string text = orzanWithPoints(kFourPoints);
  const std::string message = errorOf([&] { parseOrzanXml(text.substr(0, text.size() / 2)); });
  EXPECT_TRUE(mentions(message, "<string>")) << message;
  EXPECT_TRUE(mentions(message, "malformed XML")) << message;
}

TEST(MalformedOrzan, NanCoordinate) {
  const std::string message = errorOf([&] {
    parseOrzanXml(
        orzanWithPoints("<control_point x=\"nan\" y=\"0\"/><control_point x=\"1\" y=\"1\"/>"
                        "<control_point x=\"2\" y=\"1\"/><control_point x=\"3\" y=\"0\"/>"));
  });
  EXPECT_TRUE(mentions(message, "curve 0 control point 0")) << message;
  EXPECT_TRUE(mentions(message, "finite")) << message;
}

TEST(MalformedOrzan, ZeroLengthAndTooShortCurves) {
  const std::string same = "<control_point x=\"2\" y=\"2\"/>";
  EXPECT_TRUE(mentions(errorOf([&] { parseOrzanXml(orzanWithPoints(same + same + same + same)); }),
                       "zero-length"));
  EXPECT_TRUE(mentions(errorOf([&] { parseOrzanXml(orzanWithPoints(same)); }), "3K+1"));
  EXPECT_TRUE(mentions(errorOf([&] { parseOrzanXml(orzanWithPoints("")); }), "3K+1"));
}

TEST(MalformedOrzan, MissingAttributesAndElements) {
  EXPECT_TRUE(mentions(errorOf([&] {
                         parseOrzanXml(orzanWithPoints(
                             "<control_point x=\"0\"/><control_point x=\"1\" y=\"1\"/>"
                             "<control_point x=\"2\" y=\"1\"/><control_point x=\"3\" y=\"0\"/>"));
                       }),
                       "missing attribute y"));
  EXPECT_TRUE(
      mentions(errorOf([&] { parseOrzanXml("<curve_set image_height=\"4\"/>"); }), "image_width"));
  const std::string no_colours = kCurveHead + "<control_points_set>" + kFourPoints +
                                 "</control_points_set></curve></curve_set>";
  EXPECT_TRUE(mentions(errorOf([&] { parseOrzanXml(no_colours); }), "left_colors_set"));
  EXPECT_TRUE(mentions(errorOf([&] { parseOrzanXml("<svg/>"); }), "curve_set"));
}

TEST(MalformedOrzan, OutOfRangeValues) {
  std::string text = orzanWithPoints(kFourPoints);
  const std::string bad_id = text;
  EXPECT_TRUE(mentions(errorOf([&] {
                         std::string t = text;
                         t.replace(t.find("globalID=\"0\""), 12, "globalID=\"11\"");
                         parseOrzanXml(t);
                       }),
                       "globalID"));
  EXPECT_TRUE(mentions(errorOf([&] {
                         std::string t = text;
                         t.replace(t.find("B=\"0\""), 5, "B=\"256\"");
                         parseOrzanXml(t);
                       }),
                       "0..255"));
}

TEST(MalformedOrzan, DeclaredCountMismatchIsReported) {
  const std::string text = "<curve_set image_width=\"10\" image_height=\"10\" nb_curves=\"3\"/>";
  EXPECT_TRUE(mentions(errorOf([&] { parseOrzanXml(text); }), "nb_curves=3"));
}

TEST(MalformedOrzan, MillionControlPointsAreRejectedQuickly) {
  std::string points;
  points.reserve(1000000 * 36);
  for (int i = 0; i < 1000000; ++i) points += "<control_point x=\"1\" y=\"2\"/>";
  const std::string text = orzanWithPoints(points);
  const auto start = std::chrono::steady_clock::now();
  const std::string message = errorOf([&] { parseOrzanXml(text); });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_TRUE(mentions(message, "100000")) << message;
  EXPECT_LT(seconds, 2.0);
}

TEST(MalformedOrzan, MissingFile) {
  EXPECT_TRUE(mentions(errorOf([] { readOrzanXml("/nonexistent/file.xml"); }), "cannot open"));
}

TEST(MalformedSvg, UnknownPathCommand) {
  const std::string message = errorOf([] { parseSvg(svgWithPath("M 0 0 L 5 5 K 1 1 Z")); });
  EXPECT_TRUE(mentions(message, "'K'")) << message;
  EXPECT_TRUE(mentions(message, "<path> line 1")) << message;
}

TEST(MalformedSvg, NanAndBrokenNumbers) {
  EXPECT_TRUE(mentions(errorOf([] { parseSvg(svgWithPath("M 0 0 L nan 5 Z")); }), "number"));
  EXPECT_TRUE(mentions(errorOf([] { parseSvg(svgWithPath("M 0 0 L 1e999 5 Z")); }), "range"));
  EXPECT_TRUE(mentions(errorOf([] { parseSvg(svgWithPath("M 0 0 L 5")); }), "number"));
}

TEST(MalformedSvg, MissingAttributes) {
  EXPECT_TRUE(mentions(
      errorOf([] {
        parseSvg("<svg xmlns='http://www.w3.org/2000/svg' viewBox='0 0 9 9'><path/></svg>");
      }),
      "missing attribute d"));
  EXPECT_TRUE(mentions(errorOf([] {
                         parseSvg(
                             "<svg xmlns='http://www.w3.org/2000/svg' viewBox='0 0 9 9'>"
                             "<polygon fill='red'/></svg>");
                       }),
                       "points"));
  EXPECT_TRUE(
      mentions(errorOf([] { parseSvg("<svg><path d='M0 0 L1 1 L1 0 Z'/></svg>"); }), "viewBox"));
}

TEST(MalformedSvg, TruncatedDocumentAndWrongRoot) {
  EXPECT_TRUE(
      mentions(errorOf([] { parseSvg("<svg viewBox='0 0 9 9'><path d='M0 0"); }), "malformed XML"));
  EXPECT_TRUE(mentions(errorOf([] { parseSvg("<html/>"); }), "<svg>"));
}

TEST(MalformedSvg, ZeroLengthContoursAreDropped) {
  const DiffusionCurveImage image =
      parseSvg(svgWithPath("M 1 1 Z M 2 2 L 2 2 Z M 0 0 L 5 0 L 5 5 Z"));
  EXPECT_EQ(image.curves.size(), 1u);
}

// Found by fuzz/run_fuzz.sh: coordinates near 1e54 overflowed the flattening step count.
TEST(MalformedSvg, HugeCoordinatesDoNotOverflow) {
  const std::string path = std::string(VICC_GLYPHS_TEST_DATA_DIR) + "/fuzz_huge_coordinates.svg";
  try {
    EXPECT_TRUE(validate(importSvg(path)).empty());
  } catch (const FormatError& e) {
    EXPECT_TRUE(mentions(e.what(), path)) << e.what();
  }
  const DiffusionCurveImage image = parseSvg(svgWithPath("M 0 0 C 1e54 1e54 -1e54 1e54 5 5 Z"));
  EXPECT_FALSE(image.curves.empty());
  EXPECT_TRUE(validate(image).empty());
}

TEST(MalformedSvg, UnsupportedPaint) {
  EXPECT_TRUE(mentions(errorOf([] {
                         parseSvg(
                             "<svg viewBox='0 0 9 9'><rect width='3' height='3' "
                             "fill='url(#g)'/></svg>");
                       }),
                       "no element with id 'g'"));
  EXPECT_TRUE(mentions(
      errorOf([] {
        parseSvg("<svg viewBox='0 0 9 9'><rect width='3' height='3' fill='hsl(0, 0%, 0%)'/></svg>");
      }),
      "unsupported paint"));
}

TEST(MalformedSvg, MillionControlPointsAreRejectedQuickly) {
  std::ostringstream d;
  d << "M 0 0";
  for (int i = 0; i < 333334; ++i) d << " L " << (i % 7) << ' ' << (i % 5);
  const std::string text = svgWithPath(d.str());
  const auto start = std::chrono::steady_clock::now();
  const std::string message = errorOf([&] { parseSvg(text); });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_TRUE(mentions(message, "100000")) << message;
  EXPECT_LT(seconds, 2.0);
}

TEST(MalformedLoad, UnknownExtensionAndUnreadableImage) {
  EXPECT_TRUE(mentions(errorOf([] { loadDiffusionCurves("/tmp/icon.bmp"); }), "unknown extension"));
  const std::string path = ::testing::TempDir() + "/vicc_not_a.png";
  std::ofstream(path) << "this is not a PNG";
  EXPECT_TRUE(mentions(errorOf([&] { loadDiffusionCurves(path); }), "cannot read image"));
  std::remove(path.c_str());
}

}  // namespace
}  // namespace vicc_glyphs
