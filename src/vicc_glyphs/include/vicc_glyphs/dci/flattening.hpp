#pragma once
// How a curve becomes straight pieces. The renderer cuts the pixel lattice with these pieces,
// and PACEMOD's polygon checks search the same pieces for crossings: where two pieces cross,
// the renderer puts a curve's two sides the wrong way round (a smudge of one side's colour on
// the other), so a check on other polylines can miss exactly the crossings that show. A thin
// fold whose flanks cross 0.05 px apart near its tip is such a case: 16 points per segment miss
// it, the renderer does not.

#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"

namespace vicc_glyphs {

struct Flattening {
  /// Largest distance of a piece from the curve (pixels of the grid being drawn).
  double tolerance = 0.02;
  /// Longest piece, measured along the control polygon: short pieces keep the curve parameter,
  /// which is interpolated linearly along a piece, close to the true one.
  double max_piece_length = 2.0;
  int max_pieces = 4096;  ///< per Bezier segment
  /// Pieces at least for a segment that meets a neighbour at a fold (a corner where the curve
  /// turns by more than 120 degrees, as at a wave's sharp tip): a swallowtail there, the two
  /// sides crossing a tenth of a pixel from the corner and a hundredth apart, lies within
  /// pieces that share the corner otherwise, where no polygon check can see it.
  int pieces_beside_fold = 16;
};

/// Uniform parameter steps for the cubic Bezier segment b[0] .. b[3]: a cubic flattened into n
/// uniform pieces deviates at most 0.75 * bend / n^2 from them (bend: the larger second
/// difference of its control points); at least flattening.pieces_beside_fold if
/// `beside_fold`. At least 1, at most flattening.max_pieces; NaN input gives 1.
int flatteningPieces(const Point2* b, bool beside_fold, const Flattening& flattening = {});

/// Whether the Bezier segment `before` (4 points) and the segment `after` that starts where it
/// ends meet at a fold: their tangents there more than 120 degrees apart.
bool meetAtFold(const Point2* before, const Point2* after);

/// Per Bezier segment of `chain` (3K+1 points) whether it meets its predecessor or successor
/// (across the closing point of a closed chain) at a fold: each join tested once.
std::vector<char> segmentsBesideFolds(const std::vector<Point2>& chain);

/// segmentsBesideFolds of `curve`'s control points, for segment k (false out of range).
bool segmentBesideFold(const DiffusionCurve& curve, int k);

/// The Bezier point of b[0] .. b[3] at t in [0, 1]. Inline: called per point of every
/// flattening and sampling, from other libraries too.
inline Point2 bezierPoint(const Point2* b, double t) {
  const double u = 1.0 - t;
  return u * u * u * b[0] + 3.0 * u * u * t * b[1] + 3.0 * u * t * t * b[2] + t * t * t * b[3];
}

/// `curve`'s Bezier segments flattened as the renderer draws them at scale 1 (uniform steps per
/// segment, flatteningPieces each, the first point of the curve included once); the curve
/// parameter s of each point to `positions` if given. Empty for a curve without a segment.
std::vector<Point2> flattenCurve(const DiffusionCurve& curve,
                                 std::vector<double>* positions = nullptr,
                                 const Flattening& flattening = {});

}  // namespace vicc_glyphs
