#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "vicc_anatomy_viz/avatar_view/procedural_texture.hpp"

namespace vicc_anatomy_viz::avatar_view {
namespace {

double standardDeviation(const GreyImage& image) {
  const double mean =
      std::accumulate(image.pixels.begin(), image.pixels.end(), 0.0) / image.pixels.size();
  double sum = 0.0;
  for (auto value : image.pixels) sum += (value - mean) * (value - mean);
  return std::sqrt(sum / image.pixels.size());
}

TextureState noise(int level) { return {TextureKind::kNoise, level, 3, 8.f, 1.f}; }

TEST(ProceduralTextureTest, NoTextureIsPlainWhiteAndSizeIsWholeCells) {
  const GreyImage image = textureImage({}, 30);
  EXPECT_EQ(image.size, 32);
  EXPECT_EQ(image.pixels.size(), 32u * 32u);
  EXPECT_TRUE(
      std::all_of(image.pixels.begin(), image.pixels.end(), [](auto v) { return v == 255; }));
}

TEST(ProceduralTextureTest, NoiseContrastGrowsWithTheLevelAndKeepsTheHueReadable) {
  const double low = standardDeviation(textureImage(noise(1), 64));
  const double mid = standardDeviation(textureImage(noise(2), 64));
  const double high = standardDeviation(textureImage(noise(3), 64));
  EXPECT_GT(low, 5.0);
  EXPECT_LT(low, mid);
  EXPECT_LT(mid, high);
  const GreyImage image = textureImage(noise(3), 64);
  EXPECT_GE(*std::min_element(image.pixels.begin(), image.pixels.end()), 110);
}

TEST(ProceduralTextureTest, NormalPerturbationShadesBumpsAndTiles) {
  const GreyImage image = textureImage({TextureKind::kNormalPerturbation, 1, 1, 6.f, 0.6f}, 64);
  EXPECT_GT(standardDeviation(image), 10.0);
  // Seamless: the pattern has whole periods per tile, so column 0 matches column size.
  const int cell = image.size / kTextureCellsPerTile;
  for (int y = 0; y < image.size; ++y)
    EXPECT_NEAR(image.pixels[y * image.size], image.pixels[y * image.size + cell], 1);
}

TEST(ProceduralTextureTest, TextureCoordinatesPutFrequencyCellsOnADecimetre) {
  const Eigen::Vector2f a = textureCoordinate({0.f, 0.f, 0.f}, Eigen::Vector3f::UnitX(), 8.f);
  const Eigen::Vector2f b = textureCoordinate({0.f, 0.1f, 0.f}, Eigen::Vector3f::UnitX(), 8.f);
  // 8 cells per decimetre = one tile of kTextureCellsPerTile = 8 cells.
  EXPECT_NEAR((b - a).norm(), 8.f / kTextureCellsPerTile, 1e-5f);
  const Eigen::Vector2f c = textureCoordinate({0.3f, 0.f, 0.f}, Eigen::Vector3f::UnitX(), 8.f);
  EXPECT_NEAR((c - a).norm(), 0.f, 1e-6f);  // along the normal: no change
}

}  // namespace
}  // namespace vicc_anatomy_viz::avatar_view
