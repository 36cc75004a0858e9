#include "vicc_glyphs/render/curve_antialiasing.hpp"

#include <cstring>
#include <limits>

namespace vicc_glyphs {

void CurveAntialiasing::blend(const DiffusionCurveImage& image, int width, int height, int channels,
                              const std::vector<float>& diffused, std::vector<float>& blended) {
  blended.resize(diffused.size());
  blend(image, width, height, channels, diffused.data(), blended.data());
}

// A later crossing replaces the kept one only when strictly nearer, so that each pixel keeps the
// first of its nearest crossings in crossing order.
void CurveAntialiasing::consider(int pixel, int across, double distance, double footprint) {
  int& slot = slot_[pixel];
  if (slot < 0) {
    slot = static_cast<int>(nearest_.size());
    nearest_.push_back({pixel, -1, std::numeric_limits<float>::infinity(), 0.5f});
  }
  Nearest& kept = nearest_[slot];
  if (distance >= kept.distance) return;  // compared unrounded, as the crossings come
  kept.across = across;
  kept.distance = static_cast<float>(distance);
  kept.footprint = static_cast<float>(footprint);
}

void CurveAntialiasing::blend(const DiffusionCurveImage& image, int width, int height, int channels,
                              const float* diffused, float* blended) {
  crossings_.clear();
  forEachLatticeCrossing(image, 1.0, width, height,
                         [&](const LatticeCrossing& crossing) { crossings_.push_back(crossing); });
  blend(crossings_, width, height, channels, diffused, blended);
}

void CurveAntialiasing::blend(const LatticeCrossingList& crossings, int width, int height,
                              int channels, const float* diffused, float* blended) {
  const int n = width * height;
  if (n <= 0) return;
  std::memcpy(blended, diffused, static_cast<size_t>(n) * channels * sizeof(float));
  const auto inside = [&](const GridPixel& p) {
    return p.x >= 0 && p.y >= 0 && p.x < width && p.y < height;
  };
  if (slot_.size() != static_cast<size_t>(n) || !slots_clean_) slot_.assign(n, -1);
  slots_clean_ = false;
  nearest_.clear();
  for (const LatticeCrossing& crossing : crossings) {
    if (!inside(crossing.left_pixel) || !inside(crossing.right_pixel)) continue;
    const int left = crossing.left_pixel.y * width + crossing.left_pixel.x;
    const int right = crossing.right_pixel.y * width + crossing.right_pixel.x;
    consider(left, right, crossing.left_distance, crossing.footprint);
    consider(right, left, crossing.right_distance, crossing.footprint);
  }
  for (const Nearest& kept : nearest_) {
    slot_[kept.pixel] = -1;
    if (kept.across < 0 || kept.distance >= kept.footprint) continue;
    const float across_share = (kept.footprint - kept.distance) / (2.0f * kept.footprint);
    for (int c = 0; c < channels; ++c) {
      const size_t own = static_cast<size_t>(kept.pixel) * channels + c;
      const size_t across = static_cast<size_t>(kept.across) * channels + c;
      blended[own] = (1.0f - across_share) * diffused[own] + across_share * diffused[across];
    }
  }
  slots_clean_ = true;
}

void blendAcrossCurves(const DiffusionCurveImage& image, int width, int height, int channels,
                       std::vector<float>& values) {
  const std::vector<float> diffused = values;
  CurveAntialiasing().blend(image, width, height, channels, diffused, values);
}

}  // namespace vicc_glyphs
