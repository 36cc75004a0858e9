#pragma once
// Where diffusion curves cut the pixel lattice of one grid: every place a curve crosses the
// segment between two neighbouring pixel centres. Both the discrete problem (which couplings
// are cut, which pixels carry which side's colour) and the anti-aliasing pass are built from
// these crossings, so the two always agree on where a curve lies.

#include <functional>

#include "vicc_glyphs/dci/diffusion_curve.hpp"
#include "vicc_glyphs/render/pixel_buffer.hpp"

namespace vicc_glyphs {

/// A pixel of a grid, addressed by column x and row y (may lie outside the grid).
struct GridPixel {
  int x = 0;
  int y = 0;
};

/// One curve crossing the link between two neighbouring pixel centres.
struct LatticeCrossing {
  int curve = 0;                ///< index into DiffusionCurveImage::curves
  double position = 0.0;        ///< curve parameter s at the crossing
  GridPixel left_pixel;         ///< the neighbour on the curve's left side
  GridPixel right_pixel;        ///< the neighbour on the curve's right side
  double left_distance = 0.0;   ///< distance of the left pixel centre to the curve (grid pixels)
  double right_distance = 0.0;  ///< same for the right pixel centre
  /// Distances of the two pixel centres to the crossing point along their link (grid pixels;
  /// the two add up to 1): which crossing of a link a pixel meets first where a curve crosses
  /// the link more than once (the sharp tip of a wave or of an icon's corner).
  double left_link_distance = 0.0;
  double right_link_distance = 0.0;
  /// Half-extent of a pixel square measured along the curve normal (0.5 .. 0.707): how far
  /// from the curve a pixel centre must be for its square not to touch the curve.
  double footprint = 0.5;
};

/// Crossings kept for a second pass, in memory that a fresh renderer first-touches cheaply
/// (pixel_buffer.hpp): a glyph with high-frequency waves has tens of thousands.
using LatticeCrossingList = render_detail::PixelVector<LatticeCrossing>;

/// Calls `visit` for every crossing of the curves of `image`, scaled by `scale` (grid pixels
/// per image pixel), with a grid of `width` x `height` pixels. Crossings whose both pixels lie
/// outside the grid are skipped; curves with fewer than 3K+1 points or no length give none.
/// A curve end outside the image rectangle (image.width x image.height, before scaling) is
/// continued straight along its tangent for 2 grid pixels, so that it leaves every level's
/// grid alike (a coarse grid's last pixel row reaches further past the image border).
void forEachLatticeCrossing(const DiffusionCurveImage& image, double scale, int width, int height,
                            const std::function<void(const LatticeCrossing&)>& visit);

}  // namespace vicc_glyphs
