// The SVG painting model, checked by rendering minimal SVGs and comparing every wholly covered
// pixel with the picture SVG defines (svg_pixel_check.hpp).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "svg_pixel_check.hpp"

namespace vicc_glyphs {
namespace {

using test::expectPicture;
using test::gray;

const Color kWhite(1, 1, 1);
const Color kBlack(0, 0, 0);

std::string svg(const std::string& body) {
  return "<svg xmlns='http://www.w3.org/2000/svg' xmlns:xlink='http://www.w3.org/1999/xlink' "
         "viewBox='0 0 24 24'>" +
         body + "</svg>";
}

bool inRect(double x, double y, double x0, double y0, double w, double h) {
  return x >= x0 && x <= x0 + w && y >= y0 && y <= y0 + h;
}

TEST(SvgPainting, OverlappingShapesOfOnePaintAreOneShape) {
  expectPicture(svg("<rect x='2' y='2' width='12' height='12'/><rect x='8' y='8' width='12' "
                    "height='12'/>"),
                24, 96, [](double x, double y) {
                  return inRect(x, y, 2, 2, 12, 12) || inRect(x, y, 8, 8, 12, 12) ? kBlack : kWhite;
                });
}

TEST(SvgPainting, AbuttingShapesLeaveNoSeamOrHaze) {
  expectPicture(svg("<rect x='2' y='2' width='10' height='20'/><rect x='12' y='2' width='10' "
                    "height='20'/>"),
                24, 96,
                [](double x, double y) { return inRect(x, y, 2, 2, 20, 20) ? kBlack : kWhite; });
}

TEST(SvgPainting, CurrentColorTakesTheColorProperty) {
  auto square = [](const Color& inside) {
    return [inside](double x, double y) { return inRect(x, y, 4, 4, 16, 16) ? inside : kWhite; };
  };
  const std::string red_css =
      svg("<g style='color:#ff0000'><rect x='4' y='4' width='16' "
          "height='16' fill='currentColor'/></g>");
  expectPicture(red_css, 24, 48, square(Color(1, 0, 0)));
  const std::string inherited =
      svg("<rect x='4' y='4' width='16' height='16' fill='currentColor'/>");
  expectPicture(inherited, 24, 48, square(kBlack));  // default black
  SvgImportOptions green;
  green.current_color = Color(0, 1, 0);
  expectPicture(inherited, 24, 48, square(Color(0, 1, 0)), green);
}

TEST(SvgPainting, NothingDrawnIsAnError) {
  for (const std::string body :
       {"<path d='M2 2 H20 V20 Z' fill='none'/>", "<rect x='30' y='30' width='4' height='4'/>",
        "<g display='none'><rect width='9' height='9'/></g>", ""}) {
    try {
      parseSvg(svg(body));
      ADD_FAILURE() << "no error for " << body;
    } catch (const FormatError& e) {
      EXPECT_NE(std::string(e.what()).find("draws nothing"), std::string::npos) << e.what();
    }
  }
}

TEST(SvgPainting, StrokesBecomeFilledOutlines) {
  // A round-capped line: everything within 2 of the segment (4,12)-(20,12).
  const std::string line =
      svg("<line x1='4' y1='12' x2='20' y2='12' stroke='currentColor' stroke-width='4' "
          "stroke-linecap='round'/>");
  expectPicture(line, 24, 96, [](double x, double y) {
    const double along = std::clamp(x, 4.0, 20.0);
    return std::hypot(x - along, y - 12) <= 2.0 ? kBlack : kWhite;
  });
  // A closed square outline with miter joins: the ring between 4..20 and 8..16.
  const std::string ring =
      svg("<rect x='6' y='6' width='12' height='12' fill='none' stroke='#000' stroke-width='4'/>");
  expectPicture(ring, 24, 96, [](double x, double y) {
    return inRect(x, y, 4, 4, 16, 16) && !inRect(x, y, 8, 8, 8, 8) ? kBlack : kWhite;
  });
  // Butt caps end the stroke at the end points.
  const std::string butt =
      svg("<path d='M4 12 H20' stroke='black' stroke-width='4' stroke-linecap='butt'/>");
  expectPicture(butt, 24, 96,
                [](double x, double y) { return inRect(x, y, 4, 10, 16, 4) ? kBlack : kWhite; });
}

// Distance from (x, y) to the segment a-b.
double segmentDistance(double x, double y, double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay;
  const double t = std::clamp(((x - ax) * dx + (y - ay) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  return std::hypot(x - ax - t * dx, y - ay - t * dy);
}

TEST(SvgPainting, StrokesOfOnePaintMeetingLeaveNoGlint) {
  // Feather's "tv" (MIT): a rounded rectangle's outline and a V on its top edge. Their union
  // once kept a zero-area spike in its boundary, which became a curve rendering a light streak
  // inside the black stroke where the V meets the edge.
  const std::string tv =
      svg("<g fill='none' stroke='#000' stroke-width='2' stroke-linecap='round' "
          "stroke-linejoin='round'><rect x='2' y='7' width='20' height='15' rx='2' ry='2'/>"
          "<polyline points='17 2 12 7 7 2'/></g>");
  const auto expected = [](double x, double y) {
    // The rounded rectangle is the inner one [4, 20] x [9, 20] grown by 2.
    const double inner =
        std::hypot(std::max({4.0 - x, 0.0, x - 20.0}), std::max({9.0 - y, 0.0, y - 20.0}));
    const bool frame = std::abs(inner - 2.0) <= 1.0;
    const bool vee =
        std::min(segmentDistance(x, y, 17, 2, 12, 7), segmentDistance(x, y, 12, 7, 7, 2)) <= 1.0;
    return frame || vee ? kBlack : kWhite;
  };
  // Tolerance 0.15, not 0.03: the refit rounds the two concave corners where the V meets the
  // edge within a pixel (two pixels at 0.12). The streak was 436 pixels, up to 0.86.
  expectPicture(tv, 24, 256, expected, {}, 0.15);
}

TEST(SvgPainting, ALineTangentToARingsHoleLeavesNoStreak) {
  // From Feather's "chrome" (MIT): a ring and a line whose stroke edge is tangent to the ring's
  // inner edge. Clipper's union once joined the hole to the outer boundary by a slit of two
  // coincident edges along the line's edge through the ring; its curve sampled the background
  // as the colour across and rendered a streak of white dots in the black ring.
  const std::string ring_and_line =
      svg("<g fill='none' stroke='#000' stroke-width='2' stroke-linecap='round'>"
          "<circle cx='12' cy='12' r='4'/><line x1='10.88' y1='21.94' x2='15.46' y2='14'/></g>");
  const auto expected = [](double x, double y) {
    const bool ring = std::abs(std::hypot(x - 12.0, y - 12.0) - 4.0) <= 1.0;
    const bool line = segmentDistance(x, y, 10.88, 21.94, 15.46, 14) <= 1.0;
    return ring || line ? kBlack : kWhite;
  };
  // With the slit: 828 wrong pixels, up to 1.0.
  expectPicture(ring_and_line, 24, 256, expected, {}, 0.15);
}

TEST(SvgPainting, ACircleStandingOnAStraightEdgeLeavesNoWhiteDot) {
  // Two reels on a camera body (like Bootstrap's camera-reels): circles of one paint touching
  // each other and the body's straight top edge. The edge, fitted together with the rounded
  // corners next to it, bulged 0.027 px upwards into the circle standing on it, so each shape's
  // white outside fell inside the other: a white dot with a grey halo in the black.
  const std::string camera =
      "<svg xmlns='http://www.w3.org/2000/svg' viewBox='0 0 16 16'>"
      "<path d='M6 3a3 3 0 1 1-6 0 3 3 0 0 1 6 0'/><path d='M12 3a3 3 0 1 1-6 0 3 3 0 0 1 6 0'/>"
      "<path d='M2 6h12a2 2 0 0 1 2 2v6a2 2 0 0 1-2 2H2a2 2 0 0 1-2-2V8a2 2 0 0 1 2-2z'/></svg>";
  const auto expected = [](double x, double y) {
    const bool reel = std::hypot(x - 3.0, y - 3.0) <= 3.0 || std::hypot(x - 9.0, y - 3.0) <= 3.0;
    const double corner =
        std::hypot(std::max({2.0 - x, 0.0, x - 14.0}), std::max({8.0 - y, 0.0, y - 14.0}));
    return reel || corner <= 2.0 ? kBlack : kWhite;
  };
  // Before: wrong pixels up to 1.0 (the dot where the right reel stands on the edge).
  expectPicture(camera, 16, 512, expected);
}

TEST(SvgPainting, DashesSplitTheStroke) {
  const std::string dashed =
      svg("<path d='M2 12 H22' stroke='black' stroke-width='2' stroke-dasharray='4 2'/>");
  expectPicture(dashed, 24, 96, [](double x, double y) {
    const double phase = std::fmod(x - 2.0, 6.0);
    return y >= 11 && y <= 13 && x >= 2 && x <= 22 && phase <= 4.0 ? kBlack : kWhite;
  });
}

TEST(SvgPainting, OpacityBlendsOverTheBackground) {
  const std::string fill_opacity =
      svg("<rect x='4' y='4' width='16' height='16' fill='black' fill-opacity='0.5'/>");
  expectPicture(fill_opacity, 24, 48,
                [](double x, double y) { return inRect(x, y, 4, 4, 16, 16) ? gray(0.5) : kWhite; });
  // Two overlapping translucent shapes: the overlap is darker.
  const std::string two =
      svg("<rect x='2' y='2' width='12' height='12' opacity='0.5'/><rect x='10' y='10' width='12' "
          "height='12' opacity='0.5'/>");
  expectPicture(two, 24, 96, [](double x, double y) {
    const int n = inRect(x, y, 2, 2, 12, 12) + inRect(x, y, 10, 10, 12, 12);
    return gray(std::pow(0.5, n));
  });
  // Group opacity applies to the group as a whole: no darker overlap.
  const std::string group =
      svg("<g opacity='0.5'><rect x='2' y='2' width='12' height='12'/><rect x='10' y='10' "
          "width='12' height='12'/></g>");
  expectPicture(group, 24, 96, [](double x, double y) {
    return inRect(x, y, 2, 2, 12, 12) || inRect(x, y, 10, 10, 12, 12) ? gray(0.5) : kWhite;
  });
}

TEST(SvgPainting, UseDrawsTheReferencedElementWhereItSays) {
  const std::string use =
      svg("<defs><rect id='r' width='6' height='6'/></defs><use href='#r' x='2' y='2'/>"
          "<use xlink:href='#r' transform='translate(14 14)' fill='red'/>");
  expectPicture(use, 24, 96, [](double x, double y) {
    if (inRect(x, y, 2, 2, 6, 6)) return kBlack;
    return inRect(x, y, 14, 14, 6, 6) ? Color(1, 0, 0) : kWhite;
  });
  EXPECT_THROW(parseSvg(svg("<g id='a'><use href='#a'/></g>")), FormatError);
}

TEST(SvgPainting, StyleSheetSelectorsApplyByTypeClassAndId) {
  const std::string styled =
      svg("<style>rect { fill: #00ff00 } .red { fill: red } #blue { fill: blue }</style>"
          "<rect x='2' y='2' width='6' height='6'/><rect class='other red' x='10' y='2' width='6' "
          "height='6'/><rect id='blue' class='red' x='2' y='12' width='6' height='6'/>"
          "<rect class='red' style='fill:black' x='12' y='12' width='6' height='6'/>");
  expectPicture(styled, 24, 96, [](double x, double y) {
    if (inRect(x, y, 2, 2, 6, 6)) return Color(0, 1, 0);
    if (inRect(x, y, 10, 2, 6, 6)) return Color(1, 0, 0);
    if (inRect(x, y, 2, 12, 6, 6)) return Color(0, 0, 1);
    return inRect(x, y, 12, 12, 6, 6) ? kBlack : kWhite;
  });
}

TEST(SvgPainting, ClipPathIntersects) {
  const std::string clipped =
      svg("<clipPath id='c'><rect x='0' y='0' width='12' height='24'/></clipPath>"
          "<circle cx='12' cy='12' r='8' clip-path='url(#c)'/>");
  expectPicture(clipped, 24, 96, [](double x, double y) {
    return x <= 12 && std::hypot(x - 12, y - 12) <= 8 ? kBlack : kWhite;
  });
}

TEST(SvgPainting, CubicsThatDoubleBackStayInside) {
  // The last side runs out to x = 60 along y = 22 and back (collinear control points).
  const std::string spike = svg("<path d='M2 2 H22 V22 C 22 22 60 22 2 22 Z'/>");
  expectPicture(spike, 24, 96,
                [](double x, double y) { return inRect(x, y, 2, 2, 20, 20) ? kBlack : kWhite; });
  // A cusp: the cubic's control polygon crosses itself, so the curve folds at a point.
  const std::string cusp = svg("<path d='M4 20 C 20 4 4 4 20 20 Z'/>");
  const Point2 p0(4, 20), p1(20, 4), p2(4, 4), p3(20, 20);
  std::vector<Point2> outline;
  for (int i = 0; i <= 4000; ++i) {
    const double t = i / 4000.0, u = 1 - t;
    outline.push_back(u * u * u * p0 + 3 * u * u * t * p1 + 3 * u * t * t * p2 + t * t * t * p3);
  }
  outline.push_back(p0);
  expectPicture(cusp, 24, 96, [&](double x, double y) {
    int w = 0;
    for (std::size_t i = 0; i + 1 < outline.size(); ++i) {
      const Point2 a = outline[i], b = outline[i + 1];
      const double cross = (b.x() - a.x()) * (y - a.y()) - (x - a.x()) * (b.y() - a.y());
      if (a.y() <= y && b.y() > y && cross > 0) ++w;
      if (b.y() <= y && a.y() > y && cross < 0) --w;
    }
    return w != 0 ? kBlack : kWhite;
  });
}

std::string errorMessage(const std::string& text, int size = 0) {
  SvgImportOptions options;
  options.size = size;
  try {
    parseSvg(text, options);
  } catch (const FormatError& e) {
    return e.what();
  }
  return "";
}

TEST(SvgPainting, TooManyPixelsFailCleanly) {
  const std::string tall = "<svg viewBox='0 0 1 195'><rect width='1' height='9'/></svg>";
  EXPECT_NE(
      errorMessage(tall, 512).find("image of 512 x 99840 pixels (viewBox 1 x 195 at width 512): "
                                   "outside 1 .. 16777216 pixels (the limit)"),
      std::string::npos)
      << errorMessage(tall, 512);
  const std::string huge = "<svg viewBox='0 0 100000 100000'><rect width='9' height='9'/></svg>";
  EXPECT_NE(errorMessage(huge).find("pixels"), std::string::npos);
}

// 30,000 segments fit the control point limit, but Clipper would need minutes for them.
TEST(SvgPainting, HugeSegmentCountsFailCleanly) {
  std::string d = "M 22 12";
  for (int i = 1; i < 30000; ++i) {
    const double angle = 2.0 * M_PI * i / 30000.0, radius = i % 2 ? 9.0 : 11.0;
    d += " L " + std::to_string(12 + radius * std::cos(angle)) + " " +
         std::to_string(12 + radius * std::sin(angle));
  }
  const std::string message = errorMessage(svg("<path d='" + d + " Z'/>"), 512);
  EXPECT_NE(message.find("more than 20000 per shape"), std::string::npos) << message;
}

TEST(SvgPainting, UnsupportedFeaturesAreNamedOrWarnedAbout) {
  const std::string text = svg("<rect width='9' height='9'/><text x='1' y='20'>Hi</text>");
  EXPECT_NE(errorMessage(text).find("<text> is not supported"), std::string::npos);
  EXPECT_NE(errorMessage(svg("<rect width='9' height='9' mask='url(#m)'/>")).find("mask"),
            std::string::npos);
  EXPECT_NE(errorMessage(svg("<style>g rect { fill: red }</style><rect width='9' height='9'/>"))
                .find("CSS selector 'g rect'"),
            std::string::npos);
  for (const std::string attribute : {"marker-end='url(#m)'", "vector-effect='non-scaling-stroke'",
                                      "style='transform: scale(2)'", "paint-order='stroke'"}) {
    const std::string message = errorMessage(svg("<rect width='9' height='9' " + attribute + "/>"));
    EXPECT_NE(message.find("is not supported"), std::string::npos) << attribute << ": " << message;
  }
  EXPECT_NO_THROW(
      parseSvg(svg("<rect width='9' height='9' vector-effect='none' "
                   "paint-order='normal' marker-end='none'/>")));
  std::vector<std::string> warnings;
  SvgImportOptions lenient;
  lenient.lenient = true;
  lenient.warn = [&](const std::string& w) { warnings.push_back(w); };
  const DiffusionCurveImage image = parseSvg(text, lenient);
  EXPECT_FALSE(image.curves.empty());
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("<text>"), std::string::npos);
}

TEST(SvgPainting, NestingDepthIsLimited) {
  std::string deep;
  for (int i = 0; i < 70; ++i) deep += "<g>";
  deep += "<rect width='9' height='9'/>";
  for (int i = 0; i < 70; ++i) deep += "</g>";
  EXPECT_NE(errorMessage(svg(deep)).find("nested deeper than 64"), std::string::npos);
}

}  // namespace
}  // namespace vicc_glyphs
