#pragma once
// Which colour is seen where in a stack of filled shapes: each shape is its contours, fill
// colour and fill rule; point queries use winding numbers on flattened contours, so the
// answer follows the SVG painting model (later shapes on top, background below all).

#include <Eigen/Geometry>
#include <vector>

#include "svg_geometry.hpp"

namespace vicc_glyphs {
namespace io_detail {

enum class FillRule { kNonZero, kEvenOdd };

/// A contour flattened into a closed polyline, with its bounding box for quick rejection.
struct FlatContour {
  std::vector<Point2> points;  ///< first == last
  Eigen::AlignedBox2d box;
};

/// Flattens a contour; the vertex of each Bezier at t = 0.5 is kept exactly on the curve.
FlatContour flatten(const Contour& contour);

/// Winding number of the closed polylines around `p`.
int windingNumber(const std::vector<FlatContour>& contours, const Point2& p);

struct FilledShape {
  std::vector<Contour> contours;
  std::vector<FlatContour> flat;  ///< filled by addShape
  Color fill = Color::Zero();
  FillRule rule = FillRule::kNonZero;

  bool contains(const Point2& p) const;
};

/// The shapes of a picture in painting order, over a background colour.
class PaintedScene {
 public:
  explicit PaintedScene(const Color& background) : background_(background) {}

  void addShape(std::vector<Contour> contours, const Color& fill, FillRule rule);
  const std::vector<FilledShape>& shapes() const { return shapes_; }
  /// Colour of the topmost shape containing `p`, or the background.
  Color colorAt(const Point2& p) const;

 private:
  Color background_;
  std::vector<FilledShape> shapes_;
};

}  // namespace io_detail
}  // namespace vicc_glyphs
