#include "vicc_glyphs/render/curve_antialiasing.hpp"

#include <algorithm>
#include <cstring>
#include <limits>

#include "vicc_glyphs/render/lattice_crossings.hpp"

namespace vicc_glyphs {

void CurveAntialiasing::blend(const DiffusionCurveImage& image, int width, int height, int channels,
                              const std::vector<float>& diffused, std::vector<float>& blended) {
  blended.resize(diffused.size());
  blend(image, width, height, channels, diffused.data(), blended.data());
}

void CurveAntialiasing::blend(const DiffusionCurveImage& image, int width, int height, int channels,
                              const float* diffused, float* blended) {
  const int n = width * height;
  if (n <= 0) return;
  std::memcpy(blended, diffused, static_cast<size_t>(n) * channels * sizeof(float));
  const auto inside = [&](const GridPixel& p) {
    return p.x >= 0 && p.y >= 0 && p.x < width && p.y < height;
  };
  candidates_.clear();
  const auto consider = [&](const GridPixel& pixel, const GridPixel& across, double distance,
                            double footprint) {
    if (!inside(pixel) || !inside(across)) return;
    candidates_.push_back({pixel.y * width + pixel.x, across.y * width + across.x, distance,
                           static_cast<float>(footprint)});
  };
  forEachLatticeCrossing(image, 1.0, width, height, [&](const LatticeCrossing& crossing) {
    consider(crossing.left_pixel, crossing.right_pixel, crossing.left_distance, crossing.footprint);
    consider(crossing.right_pixel, crossing.left_pixel, crossing.right_distance,
             crossing.footprint);
  });
  // Per pixel, the first of its nearest crossings in crossing order (a stable sort keeps that
  // order within a pixel): a later crossing replaces the kept one only when strictly nearer.
  std::stable_sort(candidates_.begin(), candidates_.end(),
                   [](const Candidate& a, const Candidate& b) { return a.pixel < b.pixel; });
  for (size_t next = 0; next < candidates_.size();) {
    const int pixel = candidates_[next].pixel;
    float distance = std::numeric_limits<float>::infinity(), footprint = 0.5f;
    int across_pixel = -1;
    for (; next < candidates_.size() && candidates_[next].pixel == pixel; ++next) {
      const Candidate& candidate = candidates_[next];
      if (candidate.distance >= distance) continue;
      distance = static_cast<float>(candidate.distance);
      footprint = candidate.footprint;
      across_pixel = candidate.across;
    }
    if (across_pixel < 0 || distance >= footprint) continue;
    const float across_share = (footprint - distance) / (2.0f * footprint);
    for (int c = 0; c < channels; ++c) {
      const size_t own = static_cast<size_t>(pixel) * channels + c;
      const size_t across = static_cast<size_t>(across_pixel) * channels + c;
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
