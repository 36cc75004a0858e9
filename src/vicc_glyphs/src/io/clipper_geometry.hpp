#pragma once
// Polygon geometry for the SVG importer on Clipper (Angus Johnson's polyclipping): Bezier chains
// flattened to polylines within a tolerance, placed on an integer grid, and boolean operations
// (union, intersection, difference) that resolve overlaps, self-intersections, loops and cusps.

#include <Eigen/Geometry>
#include <clipper.hpp>
#include <initializer_list>
#include <vector>

#include "svg_geometry.hpp"

namespace vicc_glyphs {
namespace io_detail {

using ClipperLib::IntPoint;
using ClipperLib::IntRect;
using ClipperLib::Path;
using ClipperLib::Paths;

enum class FillRule { kNonZero, kEvenOdd };

/// Maps pixel coordinates to Clipper's integers: the larger image side spans 2^22 units, and
/// every coordinate stays within Clipper's fast range (|v| < 2^30).
class IntegerFrame {
 public:
  IntegerFrame() = default;
  IntegerFrame(int width, int height);

  double unitsPerPixel() const { return units_per_pixel_; }
  /// Pixel coordinates, clamped to the frame's range (far outside the image).
  IntPoint toInt(const Point2& pixel) const;
  Point2 toPixel(const IntPoint& point) const;
  /// The pixel-space box whose inside converts without clamping.
  Eigen::AlignedBox2d safeBox() const;

 private:
  double units_per_pixel_ = 1.0;
  int width_ = 1;
  int height_ = 1;
};

/// Counts polyline vertices across a file; throws std::length_error beyond the limit.
class VertexBudget {
 public:
  explicit VertexBudget(std::size_t limit) : limit_(limit) {}
  void spend(std::size_t vertices);

 private:
  std::size_t limit_;
  std::size_t used_ = 0;
};

/// Vertices one shape's flattened outline may have: Clipper's joining of output polygons is
/// quadratic in their local minima (a 30,000-point star took 10 minutes), so larger shapes
/// are refused (std::length_error) instead.
constexpr std::size_t kMaxVerticesPerShape = 20000;
/// Throws std::length_error when `vertices` exceeds kMaxVerticesPerShape.
void checkShapeVertices(std::size_t vertices);

/// Appends the flattened chain (3K+1 points) to `out`, skipping its first point when `out`
/// already ends there; every Bezier is split evenly so no chord deviates more than `tolerance`.
void flattenChain(const Contour& chain, double tolerance, VertexBudget& budget,
                  std::vector<Point2>& out);

/// Clips a closed polygon to a box (Sutherland-Hodgman), exact for the part inside.
std::vector<Point2> clipPolygonToBox(const std::vector<Point2>& polygon,
                                     const Eigen::AlignedBox2d& box);

/// The area a fill of `subpaths` (pixel coordinates) covers, as non-overlapping polygons.
Paths fillArea(const std::vector<Subpath>& subpaths, FillRule rule, const IntegerFrame& frame,
               double tolerance, VertexBudget& budget);

/// Closing then opening by `radius` pixels (miter joins, so corners stay): gaps and parts
/// narrower than 2 x radius disappear. Detail far below a pixel (a comb of sub-pixel teeth)
/// cannot be told apart by the renderer's lattice and would colour pixels on the wrong side.
Paths withoutSubpixelDetail(const Paths& area, const IntegerFrame& frame, double radius);
/// `area` offset by each of `steps` (integer units, positive outwards) in turn, miter joins up
/// to `miter_limit`: a closing is {d, -d}, an opening {-d, d}.
Paths offsetInSteps(const Paths& area, std::initializer_list<double> steps, double miter_limit);

Paths unite(const Paths& a, const Paths& b);
Paths intersect(const Paths& a, const Paths& b);
Paths subtract(const Paths& a, const Paths& b);
/// Normalises possibly overlapping polygons with the given fill rule into strictly simple ones
/// (Clipper's SimplifyPolygons: no self-intersections, touching vertices or coincident edges).
Paths simplified(const Paths& paths, FillRule rule);
/// `paths` without spikes: vertices where the boundary runs out and back along one line (the tip
/// within `width` integer units of the line through its neighbours) and repeated vertices.
/// Boolean operations leave such spikes, and a curve along one renders as a glint inside its
/// region. The test is symmetric, so a boundary shared by two regions loses the same vertices
/// in either direction; other vertices stay.
Paths withoutSpikes(const Paths& paths, double width);

/// Bounding box of `paths` (all zero when empty) and whether two boxes overlap.
IntRect boundsOf(const Paths& paths);
bool boxesOverlap(const IntRect& a, const IntRect& b);
/// The axis-aligned rectangle [x0, x1] x [y0, y1] in pixels.
Path rectangle(const IntegerFrame& frame, double x0, double y0, double x1, double y1);

}  // namespace io_detail
}  // namespace vicc_glyphs
