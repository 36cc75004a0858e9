#pragma once
// Imports raster icons (PNG files of any colour type and depth): the image is quantised into a
// few colour regions, each region's boundary is traced into cubic Beziers with potrace, and the
// colours on both sides of every curve are sampled from the image a few pixels off the curve.

#include <string>

#include "vicc_glyphs/dci/diffusion_curve.hpp"
#include "vicc_glyphs/io/format_error.hpp"

namespace vicc_glyphs {

struct RasterImportOptions {
  int max_colors = 4;                 ///< k-means clusters (colour regions) at most
  double min_color_fraction = 0.01;   ///< smaller clusters (anti-aliasing) join their neighbour
  int min_region_area = 8;            ///< potrace turdsize: speckles up to this many pixels dropped
  double corner_threshold = 1.0;      ///< potrace alphamax (0 = polygon, 1.3334 = no corners)
  double sample_offset = 2.5;         ///< pixels off the curve where side colours are sampled
  int color_samples_per_segment = 1;  ///< colour points per Bezier segment on each side
  Color alpha_background{1, 1, 1};    ///< transparent pixels are composited onto this colour
};

/// Reads and traces a raster image (at most 4096 x 4096 pixels). The colour region touching
/// the image border most is the background and is not traced itself. Throws FormatError.
DiffusionCurveImage importRaster(const std::string& path, const RasterImportOptions& options = {});

}  // namespace vicc_glyphs
