// A glyph image as flat-coloured quads: runs of equal pixels merged, the background left out,
// positions and aspect kept, the plane facing the way it is told.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <stdexcept>

#include "vicc_anatomy_viz/status_glyph/glyph_billboard.hpp"

namespace {

using namespace vicc_anatomy_viz::status_glyph;

RgbImage whiteImage(int width, int height) {
  RgbImage image;
  image.width = width;
  image.height = height;
  image.rgb.assign(static_cast<std::size_t>(width) * height * 3, 255);
  return image;
}

void paint(RgbImage& image, int x, int y, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  const std::size_t at = (static_cast<std::size_t>(y) * image.width + x) * 3;
  image.rgb[at] = r;
  image.rgb[at + 1] = g;
  image.rgb[at + 2] = b;
}

TEST(GlyphBillboardTest, AnAllBackgroundImageHasNoQuads) {
  EXPECT_TRUE(billboardQuads(whiteImage(8, 4), BillboardOptions()).empty());
}

TEST(GlyphBillboardTest, ARunOfEqualPixelsIsOneQuadAtItsPlace) {
  RgbImage image = whiteImage(10, 5);  // 0.1 m wide: 1 cm pixels, 5 cm high
  for (int x = 2; x < 6; ++x) paint(image, x, 1, 255, 0, 0);
  paint(image, 6, 1, 0, 255, 0);
  BillboardOptions options;
  options.width_m = 0.1f;
  const auto quads = billboardQuads(image, options);
  ASSERT_EQ(quads.size(), 2u);
  // Red run: pixels 2..5 of row 1; u from -0.05 + 0.02 to -0.05 + 0.06, v from 0.025 - 0.02
  // to 0.025 - 0.01 (row 0 is the top).
  EXPECT_NEAR(quads[0].min_corner.x(), -0.03f, 1e-6f);
  EXPECT_NEAR(quads[0].max_corner.x(), 0.01f, 1e-6f);
  EXPECT_NEAR(quads[0].min_corner.y(), 0.005f, 1e-6f);
  EXPECT_NEAR(quads[0].max_corner.y(), 0.015f, 1e-6f);
  EXPECT_TRUE(quads[0].colour.isApprox(Eigen::Vector3f(1, 0, 0)));
  EXPECT_NEAR(quads[1].min_corner.x(), 0.01f, 1e-6f);
  EXPECT_NEAR(quads[1].max_corner.x(), 0.02f, 1e-6f);
  EXPECT_TRUE(quads[1].colour.isApprox(Eigen::Vector3f(0, 1, 0)));
}

TEST(GlyphBillboardTest, NearWhiteIsBackgroundButLightColoursAreNot) {
  RgbImage image = whiteImage(3, 1);
  paint(image, 0, 0, 250, 252, 249);  // within 0.04 of white: anti-aliasing haze
  paint(image, 1, 0, 231, 163, 173);  // the pink of the brain before it is recoloured
  const auto quads = billboardQuads(image, BillboardOptions());
  ASSERT_EQ(quads.size(), 1u);
  EXPECT_NEAR(quads[0].colour.x(), 231.f / 255.f, 1e-6f);
}

TEST(GlyphBillboardTest, TrianglesSpanThePlaneFacingTheGivenSide) {
  RgbImage image = whiteImage(2, 2);
  paint(image, 0, 0, 0, 0, 255);
  BillboardOptions options;
  options.width_m = 0.2f;
  const auto quads = billboardQuads(image, options);
  ASSERT_EQ(quads.size(), 1u);
  const Eigen::Vector3f centre(0.f, 0.f, 1.8f);
  const auto soup =
      billboardTriangles(quads, centre, Eigen::Vector3f::UnitY(), Eigen::Vector3f::UnitZ());
  ASSERT_EQ(soup.points.size(), 6u);
  ASSERT_EQ(soup.colours.size(), 6u);
  for (const auto& p : soup.points) {
    EXPECT_FLOAT_EQ(p.x(), 0.f);
    EXPECT_GE(p.y(), -0.1f - 1e-6f);
    EXPECT_LE(p.y(), 0.f + 1e-6f);   // the top-left pixel: left half of the glyph ...
    EXPECT_GE(p.z(), 1.8f - 1e-6f);  // ... upper half
  }
  for (std::size_t t = 0; t < 6; t += 3) {
    const Eigen::Vector3f normal =
        (soup.points[t + 1] - soup.points[t]).cross(soup.points[t + 2] - soup.points[t]);
    EXPECT_GT(normal.x(), 0.f) << "triangle " << t / 3 << " faces away from +x";
  }
}

TEST(GlyphBillboardTest, BadImagesAreRefused) {
  RgbImage image = whiteImage(4, 4);
  image.rgb.pop_back();
  EXPECT_THROW(billboardQuads(image, BillboardOptions()), std::invalid_argument);
  EXPECT_THROW(billboardQuads(RgbImage(), BillboardOptions()), std::invalid_argument);
  BillboardOptions zero;
  zero.width_m = 0.f;
  EXPECT_THROW(billboardQuads(whiteImage(2, 2), zero), std::invalid_argument);
}

}  // namespace
