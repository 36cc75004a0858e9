#include "vicc_glyphs/render/curve_antialiasing.hpp"

#include <algorithm>
#include <limits>

#include "vicc_glyphs/render/lattice_crossings.hpp"

namespace vicc_glyphs {

void CurveAntialiasing::blend(const DiffusionCurveImage& image, int width, int height, int channels,
                              const std::vector<float>& diffused, std::vector<float>& blended) {
  blended = diffused;
  const int n = width * height;
  if (n <= 0) return;
  nearest_.assign(n, {std::numeric_limits<float>::infinity(), 0.5f, -1});
  const auto inside = [&](const GridPixel& p) {
    return p.x >= 0 && p.y >= 0 && p.x < width && p.y < height;
  };
  const auto consider = [&](const GridPixel& pixel, const GridPixel& across, double distance,
                            double footprint) {
    if (!inside(pixel) || !inside(across)) return;
    NearestCrossing& entry = nearest_[pixel.y * width + pixel.x];
    if (distance >= entry.distance) return;
    entry = {static_cast<float>(distance), static_cast<float>(footprint),
             across.y * width + across.x};
  };
  forEachLatticeCrossing(image, 1.0, width, height, [&](const LatticeCrossing& crossing) {
    consider(crossing.left_pixel, crossing.right_pixel, crossing.left_distance, crossing.footprint);
    consider(crossing.right_pixel, crossing.left_pixel, crossing.right_distance,
             crossing.footprint);
  });
  for (int p = 0; p < n; ++p) {
    const NearestCrossing& entry = nearest_[p];
    if (entry.across < 0 || entry.distance >= entry.footprint) continue;
    const float across_share = (entry.footprint - entry.distance) / (2.0f * entry.footprint);
    for (int c = 0; c < channels; ++c) {
      const size_t own = static_cast<size_t>(p) * channels + c;
      const size_t across = static_cast<size_t>(entry.across) * channels + c;
      blended[own] = (1.0f - across_share) * diffused[own] + across_share * diffused[across];
    }
  }
}

void blendAcrossCurves(const DiffusionCurveImage& image, int width, int height, int channels,
                       std::vector<float>& values) {
  const std::vector<float> diffused = values;
  CurveAntialiasing().blend(image, width, height, channels, diffused, values);
}

}  // namespace vicc_glyphs
