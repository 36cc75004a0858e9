#include <gtest/gtest.h>

#include "sample_images.hpp"
#include "vicc_glyphs/render/renderer.hpp"

namespace vicc_glyphs {
namespace {

cv::Vec3f at(const cv::Mat& image, int x, int y) { return image.at<cv::Vec3f>(y, x); }

void expectColor(const cv::Vec3f& actual, const Color& expected, double tolerance,
                 const std::string& where) {
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(actual[c], expected[c], tolerance) << where << " ch " << c;
}

TEST(RendererTest, ConstantClosedCurveFillsItsInsideWithItsColour) {
  DiffusionCurveImage image{96, 96, {}};
  const Color teal(0.1, 0.6, 0.55);
  image.curves.push_back(circleCurve({48, 48}, 30, teal, Color(1, 1, 1)));
  const RenderResult result = renderDiffusionCurves(image);
  ASSERT_EQ(result.image.size(), cv::Size(96, 96));
  for (int y = 20; y < 76; ++y) {
    for (int x = 20; x < 76; ++x) {
      if ((x + 0.5 - 48) * (x + 0.5 - 48) + (y + 0.5 - 48) * (y + 0.5 - 48) > 28.5 * 28.5) continue;
      expectColor(at(result.image, x, y), teal, 2e-3, std::to_string(x) + "," + std::to_string(y));
    }
  }
  expectColor(at(result.image, 2, 2), Color(1, 1, 1), 2e-3, "outside");
}

TEST(RendererTest, LeftColourIsOnTheLeftWhenWalkingAlongTheCurve) {
  // Drawn upwards: the walker's left is screen left.
  const RenderResult up = renderDiffusionCurves(twoColourLineImage(100, 60));
  expectColor(at(up.image, 10, 30), Color(1, 0, 0), 1e-3, "left of upward line");
  expectColor(at(up.image, 90, 30), Color(0, 0, 1), 1e-3, "right of upward line");
  // Drawn downwards the walker's left is screen right.
  DiffusionCurveImage down{100, 60, {}};
  down.curves.push_back(lineCurve({45, -2}, {45, 62}, Color(1, 0, 0), Color(0, 0, 1)));
  const RenderResult result = renderDiffusionCurves(down);
  expectColor(at(result.image, 10, 30), Color(0, 0, 1), 1e-3, "screen left of downward line");
  expectColor(at(result.image, 90, 30), Color(1, 0, 0), 1e-3, "screen right of downward line");
}

TEST(RendererTest, BarrierBlocksDiffusion) {
  const DiffusionCurveImage image = barrierImage(128, 96);
  const RenderResult blocked = renderDiffusionCurves(image);
  // Each half only sees its own circle's constant colour.
  expectColor(at(blocked.image, 62, 10), Color(1, 0, 0), 2e-3, "left of barrier");
  expectColor(at(blocked.image, 65, 10), Color(0, 0, 1), 2e-3, "right of barrier");
  DiffusionCurveImage open = image;
  open.curves.erase(open.curves.begin());  // without the barrier the colours mix
  const RenderResult mixed = renderDiffusionCurves(open);
  EXPECT_GT(at(mixed.image, 62, 10)[2], 0.2);
  EXPECT_GT(at(mixed.image, 65, 10)[0], 0.2);
}

TEST(RendererTest, AntialiasingBlendsPixelsTheCurveCuts) {
  DiffusionCurveImage image{40, 20, {}};
  // Upward line through x = 20.5, the centre of column 20: half of that pixel on each side.
  image.curves.push_back(lineCurve({20.5, 22}, {20.5, -2}, Color(1, 0, 0), Color(0, 0, 1)));
  RenderOptions options;
  const RenderResult smooth = renderDiffusionCurves(image, options);
  const cv::Vec3f cut = at(smooth.image, 20, 10);
  EXPECT_NEAR(cut[0], 0.5, 0.02);
  EXPECT_NEAR(cut[2], 0.5, 0.02);
  expectColor(at(smooth.image, 18, 10), Color(1, 0, 0), 1e-3, "one pixel further left");
  options.antialias = false;
  const RenderResult hard = renderDiffusionCurves(image, options);
  const cv::Vec3f raw = at(hard.image, 20, 10);
  EXPECT_TRUE(raw[0] > 0.99 || raw[2] > 0.99);
}

TEST(RendererTest, BlurPointsSoftenTheEdge) {
  DiffusionCurveImage image{80, 40, {}};
  DiffusionCurve line = lineCurve({40.2, 42}, {40.2, -2}, Color(1, 0, 0), Color(0, 0, 1));
  image.curves.push_back(line);
  const RenderResult sharp = renderDiffusionCurves(image);
  image.curves.front().blur_points = {{0.0, 4.0}};
  const RenderResult blurred = renderDiffusionCurves(image);
  EXPECT_FALSE(sharp.report.blurred);
  EXPECT_TRUE(blurred.report.blurred);
  EXPECT_GT(at(sharp.image, 37, 20)[0], 0.99);
  EXPECT_LT(at(blurred.image, 37, 20)[0], 0.95);  // three pixels from the edge, sigma 4
  EXPECT_GT(at(blurred.image, 37, 20)[0], 0.6);
}

TEST(RendererTest, ReusedRendererGivesTheSameResultAsAFreshOne) {
  DiffusionCurveRenderer renderer;
  RenderResult result;
  const DiffusionCurveImage first = iconLikeImage(120, 90);
  const DiffusionCurveImage second = barrierImage(120, 90);  // same size: buffers reused as is
  const DiffusionCurveImage third = gradientCircleImage(64, 80);
  for (const DiffusionCurveImage* image : {&first, &second, &third, &first}) {
    renderer.render(*image, {}, result);
    const RenderResult fresh = renderDiffusionCurves(*image);
    ASSERT_EQ(result.image.size(), fresh.image.size());
    EXPECT_EQ(cv::norm(result.image, fresh.image, cv::NORM_INF), 0.0);
    EXPECT_EQ(cv::norm(result.diffused, fresh.diffused, cv::NORM_INF), 0.0);
  }
}

TEST(RendererTest, SizeOptionScalesTheImage) {
  RenderOptions options;
  options.size = 50;
  const RenderResult result = renderDiffusionCurves(twoColourLineImage(100, 60), options);
  EXPECT_EQ(result.image.size(), cv::Size(50, 30));
  expectColor(at(result.image, 5, 15), Color(1, 0, 0), 1e-3, "left");
}

}  // namespace
}  // namespace vicc_glyphs
