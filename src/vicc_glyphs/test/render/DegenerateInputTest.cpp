#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <string>

#include "sample_images.hpp"
#include "vicc_glyphs/render/renderer.hpp"

namespace vicc_glyphs {
namespace {

void expectUniform(const cv::Mat& image, const Color& color) {
  ASSERT_FALSE(image.empty());
  cv::Mat difference;
  cv::absdiff(image, cv::Scalar(color[0], color[1], color[2]), difference);
  double largest = 0.0;
  cv::minMaxLoc(difference.reshape(1), nullptr, &largest);
  EXPECT_LT(largest, 1e-6);
}

RenderOptions withBackground(const Color& background) {
  RenderOptions options;
  options.background = background;
  return options;
}

TEST(DegenerateInputTest, ImageWithoutPixelsGivesEmptyResult) {
  const RenderResult result = renderDiffusionCurves(DiffusionCurveImage{});
  EXPECT_TRUE(result.image.empty());
  EXPECT_TRUE(result.diffused.empty());
}

TEST(DegenerateInputTest, ImageWithoutCurvesIsTheBackground) {
  const Color background(0.2, 0.3, 0.4);
  expectUniform(renderDiffusionCurves({32, 24, {}}, withBackground(background)).image, background);
}

// The report says whether any curve coloured a pixel; requireSomethingDrawn turns a picture
// of only the background into an error naming what was rendered.
TEST(DegenerateInputTest, TheReportCountsThePixelsACurveColoured) {
  DiffusionCurveImage outside{32, 32, {}};
  outside.curves.push_back(circleCurve({200, -300}, 20, Color(1, 0, 0), Color(0, 0, 1)));
  for (const DiffusionCurveImage& nothing : {DiffusionCurveImage{32, 24, {}}, outside}) {
    const RenderResult result = renderDiffusionCurves(nothing);
    EXPECT_EQ(result.report.curve_pixels, 0);
    try {
      requireSomethingDrawn(result.report, "icon.svg");
      ADD_FAILURE() << "no error";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("icon.svg: nothing to draw"), std::string::npos);
    }
  }
  DiffusionCurveImage circle{32, 32, {}};
  circle.curves.push_back(circleCurve({16, 16}, 8, Color(1, 0, 0), Color(0, 0, 1)));
  const RenderResult drawn = renderDiffusionCurves(circle);
  // Every lattice link the circle crosses fixes a pixel on either side: about 4 per pixel of
  // its circumference's extent, far more than none.
  EXPECT_GT(drawn.report.curve_pixels, 50);
  EXPECT_LT(drawn.report.curve_pixels, 32 * 32);
  EXPECT_NO_THROW(requireSomethingDrawn(drawn.report, "circle"));
}

TEST(DegenerateInputTest, ZeroLengthCurveIsIgnored) {
  DiffusionCurveImage image{32, 32, {}};
  image.curves.push_back(lineCurve({16, 16}, {16, 16}, Color(1, 0, 0), Color(0, 0, 1)));
  expectUniform(renderDiffusionCurves(image).image, Color::Zero());
}

TEST(DegenerateInputTest, CurveOutsideTheImageIsIgnored) {
  DiffusionCurveImage image{32, 32, {}};
  image.curves.push_back(circleCurve({200, -300}, 20, Color(1, 0, 0), Color(0, 0, 1)));
  expectUniform(renderDiffusionCurves(image, withBackground(Color(1, 1, 1))).image, Color(1, 1, 1));
}

TEST(DegenerateInputTest, MalformedCurvesAreIgnored) {
  DiffusionCurveImage image{16, 16, {}};
  DiffusionCurve two_points;
  two_points.control_points = {{0, 0}, {16, 16}};
  image.curves.push_back(two_points);
  DiffusionCurve not_finite = lineCurve({0, 8}, {16, 8}, Color(1, 0, 0), Color(0, 0, 1));
  not_finite.control_points[1].x() = std::numeric_limits<double>::quiet_NaN();
  image.curves.push_back(not_finite);
  expectUniform(renderDiffusionCurves(image).image, Color::Zero());
}

TEST(DegenerateInputTest, TinyImagesRender) {
  for (const auto& [w, h] :
       {std::pair{1, 1}, std::pair{1, 7}, std::pair{3, 2}, std::pair{600, 1}}) {
    const RenderResult result = renderDiffusionCurves(twoColourLineImage(w, h));
    EXPECT_EQ(result.image.size(), cv::Size(w, h));
    EXPECT_TRUE(cv::checkRange(result.image));
  }
}

// A thin viewBox scaled to a width, or a huge declared size, must fail before any allocation
// (it used to grow to 5 GB and die with std::bad_alloc).
TEST(DegenerateInputTest, TooManyPixelsAreRefusedWithTheLimit) {
  DiffusionCurveImage tall = twoColourLineImage(1, 195);
  RenderOptions options;
  options.size = 512;  // 512 x 99,840
  try {
    renderDiffusionCurves(tall, options);
    ADD_FAILURE() << "no error";
  } catch (const std::length_error& e) {
    EXPECT_NE(std::string(e.what()).find("limit of 16777216 pixels"), std::string::npos)
        << e.what();
  }
  DiffusionCurveImage huge = twoColourLineImage(4, 4);
  huge.width = huge.height = 100000;
  EXPECT_THROW(renderDiffusionCurves(huge), std::length_error);
}

}  // namespace
}  // namespace vicc_glyphs
