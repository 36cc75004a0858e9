#pragma once
// Anti-aliasing of the diffused image along the curves. The diffusion is solved at the output
// resolution, where each curve falls between pixel centres; a pixel whose square the curve
// cuts should show both sides in proportion to the area each covers. For every pixel next to
// a curve the nearest crossing gives the distance d of its centre to the curve and the pixel
// across it; the pixel becomes (1 - a) * own + a * across with the covered fraction
// a = (h - d) / (2h) for d < h, h the pixel's half-extent along the curve normal.

#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"

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

 private:
  // A crossing next to `pixel`; only pixels next to a curve have any, so they are kept in a
  // list (a few thousand at 512 x 512) rather than in a per-pixel array.
  struct Candidate {
    int pixel;
    int across;       // pixel index on the other side of the curve
    double distance;  // compared unrounded, as the crossings come
    float footprint;
  };
  std::vector<Candidate> candidates_;
};

/// One-off, in-place version of CurveAntialiasing::blend.
void blendAcrossCurves(const DiffusionCurveImage& image, int width, int height, int channels,
                       std::vector<float>& values);

}  // namespace vicc_glyphs
