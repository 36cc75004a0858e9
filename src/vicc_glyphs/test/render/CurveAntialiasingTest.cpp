#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <vector>

#include "sample_images.hpp"
#include "vicc_glyphs/render/curve_antialiasing.hpp"
#include "vicc_glyphs/render/lattice_crossings.hpp"

namespace vicc_glyphs {
namespace {

// The rule written out directly: per pixel the crossings next to it in crossing order, the
// first of the nearest ones decides; the pixel mixes with the one across that crossing by the
// share of its square the curve cuts off.
std::vector<float> blendByDefinition(const DiffusionCurveImage& image, int width, int height,
                                     const std::vector<float>& diffused) {
  struct Kept {
    float distance = std::numeric_limits<float>::infinity();
    float footprint = 0.5f;
    int across = -1;
  };
  std::vector<Kept> kept(static_cast<size_t>(width) * height);
  forEachLatticeCrossing(image, 1.0, width, height, [&](const LatticeCrossing& c) {
    const auto inside = [&](const GridPixel& p) {
      return p.x >= 0 && p.y >= 0 && p.x < width && p.y < height;
    };
    if (!inside(c.left_pixel) || !inside(c.right_pixel)) return;
    const int left = c.left_pixel.y * width + c.left_pixel.x;
    const int right = c.right_pixel.y * width + c.right_pixel.x;
    for (const auto& [own, across, distance] :
         {std::tuple<int, int, double>{left, right, c.left_distance},
          std::tuple<int, int, double>{right, left, c.right_distance}}) {
      if (distance >= kept[own].distance) continue;
      kept[own] = {static_cast<float>(distance), static_cast<float>(c.footprint), across};
    }
  });
  std::vector<float> blended = diffused;
  for (size_t p = 0; p < kept.size(); ++p) {
    if (kept[p].across < 0 || kept[p].distance >= kept[p].footprint) continue;
    const float share = (kept[p].footprint - kept[p].distance) / (2.0f * kept[p].footprint);
    for (int c = 0; c < 3; ++c) {
      const float own = diffused[p * 3 + c], across = diffused[kept[p].across * 3 + c];
      blended[p * 3 + c] = (1.0f - share) * own + share * across;
    }
  }
  return blended;
}

std::vector<float> noise(int width, int height, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> value(0.0f, 1.0f);
  std::vector<float> field(static_cast<size_t>(width) * height * 3);
  for (float& v : field) v = value(random);
  return field;
}

TEST(CurveAntialiasingTest, EachPixelTakesTheFirstOfItsNearestCrossings) {
  // Reused across images and sizes: what one call keeps per pixel must not leak into the next.
  CurveAntialiasing antialiasing;
  const std::vector<DiffusionCurveImage> images = {iconLikeImage(120, 90),
                                                   zigzagImage(96, 9, 0.2, 0.4),
                                                   barrierImage(120, 90), iconLikeImage(120, 90)};
  unsigned seed = 1;
  for (const DiffusionCurveImage& image : images) {
    const std::vector<float> diffused = noise(image.width, image.height, seed++);
    std::vector<float> blended;
    antialiasing.blend(image, image.width, image.height, 3, diffused, blended);
    const std::vector<float> expected =
        blendByDefinition(image, image.width, image.height, diffused);
    ASSERT_EQ(blended.size(), expected.size());
    int changed = 0;
    for (size_t i = 0; i < expected.size(); ++i) {
      ASSERT_EQ(blended[i], expected[i]) << "value " << i << " of image " << seed - 1;
      changed += blended[i] != diffused[i];
    }
    EXPECT_GT(changed, 100) << "the curves cut pixels of image " << seed - 1;
  }
}

}  // namespace
}  // namespace vicc_glyphs
