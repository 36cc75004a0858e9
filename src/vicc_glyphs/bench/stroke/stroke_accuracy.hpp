#pragma once
// How closely a stroke outline follows the true stroke: the cases and the measurement shared by
// the outliner bench (stroke_outliner_bench.cpp, which prints the table of
// bench/fidelity/README.md, session 18) and CurveStrokeTest (which asserts on it).
//
// With round caps and joins every boundary point of the true stroke lies at exactly width / 2
// from the centreline, so each outline vertex's distance to the centreline, minus width / 2, is
// the outline's error there.

#include <string>
#include <vector>

#include "clipper_geometry.hpp"
#include "svg_stroke.hpp"

namespace vicc_glyphs {
namespace io_detail {
namespace stroke_accuracy {

/// The frame of the accuracy cases: 256 x 256 px, tolerance = the importer's (256 / 8192 px).
constexpr int kFrameSize = 256;
constexpr double kTolerance = kFrameSize / 8192.0;
const IntegerFrame& caseFrame();

/// An open subpath of one cubic.
Subpath cubicSubpath(const Point2& a, const Point2& b, const Point2& c, const Point2& d);
/// A closed circle of four cubics.
Subpath circleSubpath(const Point2& centre, double radius);
/// Round caps and joins.
StrokeGeometry roundStroke(double width);

struct AccuracyCase {
  std::string name;
  std::vector<Subpath> subpaths;
  double width;
};
/// Smooth arcs, an S-curve, a U-turn tighter than the stroke, a loop, a cusp, a circle, a wide
/// arc and a Feather-like 2-unit stroke at 256 px.
std::vector<AccuracyCase> accuracyCases();

/// Distance from `p` to the cubic chain (nearest of dense samples, refined by Newton steps).
double distanceToChain(const Contour& chain, const Point2& p);

struct Deviation {
  double max = 0.0, mean = 0.0;  ///< px
  std::size_t vertices = 0;
};
/// Deviation of the vertices of `area` (integers of `frame`) from `half` = width / 2 away from
/// the centrelines `subpaths`.
Deviation deviation(const Paths& area, const IntegerFrame& frame,
                    const std::vector<Subpath>& subpaths, double half);

}  // namespace stroke_accuracy
}  // namespace io_detail
}  // namespace vicc_glyphs
