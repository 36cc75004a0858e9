#pragma once
// Anti-aliasing of the diffused image along the curves. The diffusion is solved at the output
// resolution, where each curve falls between pixel centres; a pixel whose square the curve
// cuts should show both sides in proportion to the area each covers. For every pixel next to
// a curve the nearest crossing gives the distance d of its centre to the curve and the pixel
// across it; the pixel becomes (1 - a) * own + a * across with the covered fraction
// a = (h - d) / (2h) for d < h, h the pixel's half-extent along the curve normal.

#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"
#include "vicc_glyphs/render/lattice_crossings.hpp"

namespace vicc_glyphs {

/// Blends the diffusion across curves, keeping its scratch memory between calls.
class CurveAntialiasing {
 public:
  /// `diffused`: width*height*channels values, pixel-major (the diffusion at scale 1 of
  /// `image`); writes the blended values to `blended` (not aliasing `diffused`).
  void blend(const DiffusionCurveImage& image, int width, int height, int channels,
             const std::vector<float>& diffused, std::vector<float>& blended);
  /// As above on raw buffers of width*height*channels floats (e.g. cv::Mat pixels).
  void blend(const DiffusionCurveImage& image, int width, int height, int channels,
             const float* diffused, float* blended);
  /// As above with the image's lattice crossings at scale 1 on the width x height grid, in
  /// forEachLatticeCrossing's order (e.g. GridAssembler::colorCrossings()).
  void blend(const LatticeCrossingList& crossings, int width, int height, int channels,
             const float* diffused, float* blended);

 private:
  // The nearest crossing next to `pixel` so far; only pixels next to a curve have any, so
  // they are kept in a list (a few thousand at 512 x 512, tens of thousands for a glyph with
  // high-frequency waves), found through `slot_`.
  struct Nearest {
    int pixel;
    int across;      // pixel index on the other side of the curve; -1 while none is nearer
    float distance;  // than this (+inf at first)
    float footprint;
  };
  void consider(int pixel, int across, double distance, double footprint);

  LatticeCrossingList crossings_;  // of the image, for the overloads that take one
  std::vector<Nearest> nearest_;
  // Per pixel its index in nearest_, or -1: all -1 between calls (each call resets the
  // entries it set), so the array is filled once per image size; in huge pages like the
  // renderer's other per-pixel buffers (a fresh renderer first-touches it).
  render_detail::PixelVector<int> slot_;
  // False from a call's first slot until its last reset: a call that threw in between (out of
  // memory) left entries that the next call must not trust.
  bool slots_clean_ = true;
};

/// One-off, in-place version of CurveAntialiasing::blend.
void blendAcrossCurves(const DiffusionCurveImage& image, int width, int height, int channels,
                       std::vector<float>& values);

}  // namespace vicc_glyphs
