#pragma once
// The discrete diffusion problem of one grid (one multigrid level or the output raster):
// a 5-point graph Laplacian whose links are cut where a curve passes between two pixel
// centres, with Dirichlet pixels next to each curve carrying that side's value. Image borders
// are Neumann (no links leave the grid). The multigrid solver and the tests' direct reference
// solve both read exactly this structure, so they solve the same problem.
//
// Equation at a free pixel p:  sum over coupled neighbours q of (u_p - u_q) = 0.
// A pixel next to several crossings takes the value of the nearest (the mean of equally near).
// Free pixels that no chain of links connects to a Dirichlet pixel (e.g. enclosed by barriers
// only, or an image without curves) would make the problem singular: they become Dirichlet
// pixels with the background value.

#include <cstdint>
#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"
#include "vicc_glyphs/render/lattice_crossings.hpp"
#include "vicc_glyphs/render/pixel_buffer.hpp"

namespace vicc_glyphs {

struct GridProblem {
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<std::uint8_t> couples_right;  ///< link (x,y)-(x+1,y) kept; index y*width+x
  std::vector<std::uint8_t> couples_down;   ///< link (x,y)-(x,y+1) kept
  std::vector<std::uint8_t> fixed;          ///< 1 = Dirichlet pixel
  /// Dirichlet values, pixel-major (values[pixel * channels + channel]); 0 at free pixels.
  std::vector<float> values;
  /// Dirichlet pixels that take their value from a curve (the others took the background):
  /// 0 means that no curve with colours reaches the grid and the picture is the background.
  int curve_pixels = 0;

  int pixelCount() const { return width * height; }
  float value(int channel, int pixel) const { return values[pixel * channels + channel]; }
};

/// Assembles grid problems, keeping its scratch memory and the problems' storage between
/// calls (a renderer re-assembles every level for every image).
class GridAssembler {
 public:
  /// The colour problem: RGB Dirichlet values from the emitting sides of the curves of
  /// `image` scaled by `scale` onto a `width` x `height` grid; barrier sides only cut links.
  void assembleColor(const DiffusionCurveImage& image, int width, int height, double scale,
                     const Color& background, GridProblem& problem);
  /// The blur problem (Orzan's blur field): one channel, the curve's blur sigma (in grid
  /// pixels) on both sides of every curve, 0 where a curve has no blur points.
  void assembleBlur(const DiffusionCurveImage& image, int width, int height, double scale,
                    GridProblem& problem);
  /// The lattice crossings the last assembleColor was built from, in their order: the
  /// anti-aliasing pass needs the same ones and takes them from here instead of cutting the
  /// curves with the lattice again.
  const LatticeCrossingList& colorCrossings() const { return color_crossings_; }

 private:
  LatticeCrossingList color_crossings_;
  render_detail::PixelVector<int> counts_;
  render_detail::PixelVector<float> nearest_;
  render_detail::PixelVector<std::uint8_t> reached_;
  std::vector<int> queue_;
};

/// Spreads the non-zero `labels` (one per pixel) over the links into the pixels labelled 0,
/// breadth first from the labelled pixels linked to one: each takes the label of the pixel it
/// is reached from. Pixels that no link joins to a labelled one keep 0. `queue` is scratch.
void spreadLabelsOverLinks(const GridProblem& problem, std::uint8_t* labels,
                           std::vector<int>& queue);

/// One-off versions of GridAssembler's functions.
GridProblem assembleColorProblem(const DiffusionCurveImage& image, int width, int height,
                                 double scale, const Color& background);
GridProblem assembleBlurProblem(const DiffusionCurveImage& image, int width, int height,
                                double scale);

}  // namespace vicc_glyphs
