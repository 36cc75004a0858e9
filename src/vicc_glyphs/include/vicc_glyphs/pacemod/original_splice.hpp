#pragma once
// Where a wave is flat (consecutive knot points translated by exactly 0: the skeleton guard's
// answer at a point where the contour touches another one, or the crossing repair's last round),
// the modified contour is the original there instead of a re-fit of it. A re-fit deviates by
// up to a few tenths of a pixel, and where two contours touch (two circles side by side, a
// circle sitting on a rectangle) any deviation crosses the other contour, so that the repair
// rounds flattened the waves further and further without ever removing the crossing.

#include <vector>

#include "vicc_glyphs/bspline/arc_length.hpp"
#include "vicc_glyphs/bspline/bspline_curve.hpp"
#include "vicc_glyphs/pacemod/wave_layout.hpp"

namespace vicc_glyphs {
namespace pacemod {

/// The arc-length intervals between consecutive knot points that are all translated by 0:
/// maximal runs of at least two entries with translations[i] == 0 and increasing parameters,
/// whose two ends the curve meets (not `unmet`); increasing and disjoint (a run that would start
/// before the previous one ends is left out). The inputs are per knot point, in order.
std::vector<ArcInterval> flatRuns(const std::vector<double>& parameters,
                                  const std::vector<double>& translations,
                                  const std::vector<bool>& unmet);

/// `wave` (a cubic over [0, L], L = the original's arc length, parametrised by it) with each of
/// `runs` (increasing, disjoint, within [0, L]) replaced by the original contour's stretch
/// between the same arc lengths, its parameter interval mapped affinely onto the run's. The
/// joins are C0 (triple knots at the runs' ends; the original's point is the join); elsewhere
/// the knots and de Boor points are the wave's. `table` is the original's arc-length table.
/// Throws std::invalid_argument for runs that are not increasing, disjoint and in the domain.
bspline::BSplineCurve spliceOriginal(const bspline::BSplineCurve& wave,
                                     const bspline::BSplineCurve& original,
                                     const bspline::ArcLengthTable& table,
                                     const std::vector<ArcInterval>& runs);

}  // namespace pacemod
}  // namespace vicc_glyphs
