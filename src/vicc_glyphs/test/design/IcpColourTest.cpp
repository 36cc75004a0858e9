// Intracranial pressure design (thesis Fig. 6.20), measured on rendered pixels: the category
// colours the whole brain in its traffic-light colour, at every inflation, and none of the
// icon's pink is left (a pathological pressure must never look like the normal icon).
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "shipped_designs.hpp"
#include "vicc_glyphs/design/design_builder.hpp"
#include "vicc_glyphs/pacemod/polyline.hpp"
#include "vicc_glyphs/render/renderer.hpp"

using namespace vicc_glyphs;
using namespace vicc_glyphs::design;
using vicc_glyphs::design::test::model;
using vicc_glyphs::design::test::shipped;

namespace {

constexpr int kSize = 96;
const Color kIconPink = Color(0xe7, 0xa3, 0xad) / 255.0;
const Color kCategoryColors[] = {Color(0x3a, 0xa6, 0x55) / 255.0,   // normal: green
                                 Color(0xf2, 0xb7, 0x05) / 255.0,   // elevated: yellow
                                 Color(0x9b, 0x11, 0x1e) / 255.0};  // pathological: red
// "Is this colour": within 10 of 255 (Euclidean RGB); "looks pink": within 40.
constexpr double kSameColor = 10.0 / 255.0;
constexpr double kLooksPink = 40.0 / 255.0;

double distance(const cv::Vec3f& pixel, const Color& rgb) {
  return (Color(pixel[0], pixel[1], pixel[2]) - rgb).norm();
}

// The brain outline (curve 1) filled, on the pixel grid.
cv::Mat brainRegion(const DiffusionCurveImage& glyph) {
  std::vector<cv::Point> polygon;
  for (const Point2& p : pacemod::sampleCurve(glyph.curves[1], 8)) {
    polygon.emplace_back(static_cast<int>(std::lround(p.x() - 0.5)),
                         static_cast<int>(std::lround(p.y() - 0.5)));
  }
  cv::Mat mask = cv::Mat::zeros(glyph.height, glyph.width, CV_8U);
  cv::fillPoly(mask, std::vector<std::vector<cv::Point>>{polygon}, 255);
  return mask;
}

// 2 px either side of a region's outline: anti-aliased blends of the two sides (red and skin
// mix to a pinkish tone there).
cv::Mat outlineBand(const cv::Mat& region) {
  const cv::Mat disc = cv::getStructuringElement(cv::MORPH_ELLIPSE, {5, 5});
  cv::Mat inner, outer;
  cv::erode(region, inner, disc);
  cv::dilate(region, outer, disc);
  return outer - inner;
}

struct ColourCount {
  int brain = 0;      // pixels of the brain interior
  int on_target = 0;  // of those, in the category colour
  int pink = 0;       // pixels of the whole glyph that look like the icon's pink
};

ColourCount countColours(double pressure, int category) {
  const GlyphDesign design = shipped("intracranial_pressure");
  const DiffusionCurveImage glyph = buildGlyph(
      design, design.levelsFor({{"pressure", pressure}, {"category", category}}), model(), kSize);
  const cv::Mat rendered = renderDiffusionCurves(glyph).image;
  const cv::Mat brain = brainRegion(glyph);
  const cv::Mat band = outlineBand(brain);
  ColourCount count;
  for (int y = 0; y < rendered.rows; ++y) {
    for (int x = 0; x < rendered.cols; ++x) {
      if (band.at<uint8_t>(y, x)) continue;
      const cv::Vec3f pixel = rendered.at<cv::Vec3f>(y, x);
      if (distance(pixel, kIconPink) < kLooksPink) ++count.pink;
      if (!brain.at<uint8_t>(y, x)) continue;
      ++count.brain;
      if (distance(pixel, kCategoryColors[category]) < kSameColor) ++count.on_target;
    }
  }
  return count;
}

}  // namespace

TEST(IcpColour, IconHasOneCurvePerPartAndCurveOneEnclosesTheBrain) {
  const DiffusionCurveImage icon = loadIcon(shipped("intracranial_pressure"), kSize);
  ASSERT_EQ(icon.curves.size(), 2u);  // head, brain
  const DiffusionCurve& brain = icon.curves[1];
  const bool inside_is_left = pacemod::polylineArea(pacemod::sampleCurve(brain, 8)) < 0.0;
  const Color inside = inside_is_left ? brain.leftColorAt(0.5) : brain.rightColorAt(0.5);
  EXPECT_LT((inside - kIconPink).norm(), 1e-3);
}

// The SVG import makes one curve per region boundary (the head's hole is the brain's outline),
// so curve numbers name whole icon parts at every size.
TEST(IcpColour, HeadBrainIconHasTwoCurvesAtEverySize) {
  for (int size : {32, 48, 160, 512}) {
    EXPECT_EQ(loadIcon(shipped("intracranial_pressure"), size).curves.size(), 2u) << size;
  }
}

TEST(IcpColour, EachCategoryPaintsTheWholeBrainAndNoPinkRemains) {
  // 10 mmHg: no inflation; 27 and 45 mmHg: inflated by 0.7 and 1.6 mm.
  for (double pressure : {10.0, 27.0, 45.0}) {
    for (int category = 0; category < 3; ++category) {
      const ColourCount count = countColours(pressure, category);
      SCOPED_TRACE("pressure " + std::to_string(pressure) + ", category " +
                   std::to_string(category));
      ASSERT_GT(count.brain, 600);  // the brain is a large part of a 96 px glyph
      EXPECT_GT(count.on_target, 0.9 * count.brain) << count.on_target << " of " << count.brain;
      EXPECT_EQ(count.pink, 0);
    }
  }
}
