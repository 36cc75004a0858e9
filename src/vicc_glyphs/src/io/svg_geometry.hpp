#pragma once
// Geometry shared by the SVG importer parts: contours as chains of cubic Beziers, and a budget
// that bounds how many control points one file may produce.

#include <cstddef>
#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"

namespace vicc_glyphs {
namespace io_detail {

/// A closed chain of K cubic Beziers, 3K+1 points, first == last.
using Contour = std::vector<Point2>;

/// One subpath as drawn: a chain of K cubic Beziers (3K+1 points). `closed` is true when the
/// path closed it (Z, or a closed basic shape; the closing line is then part of the points);
/// an open subpath is closed implicitly for filling but stroked with end caps.
struct Subpath {
  Contour points;
  bool closed = false;
};

/// The fill contours of subpaths: open ones get their implicit closing line.
std::vector<Contour> closedContours(std::vector<Subpath> subpaths);

/// Counts control points across a whole file; throws std::length_error beyond the limit.
class PointBudget {
 public:
  explicit PointBudget(std::size_t limit) : limit_(limit) {}
  void spend(std::size_t points);

 private:
  std::size_t limit_;
  std::size_t used_ = 0;
};

/// Builds contours segment by segment: straight lines become cubics with their inner control
/// points at thirds (a non-zero tangent everywhere), closing adds the line back to the start.
class ContourBuilder {
 public:
  explicit ContourBuilder(PointBudget& budget) : budget_(budget) {}

  void moveTo(const Point2& p);
  void lineTo(const Point2& p);
  void cubicTo(const Point2& c1, const Point2& c2, const Point2& p);
  /// Closes the current subpath with a line back to its start (SVG Z).
  void close();
  /// Ends the last subpath and returns all non-degenerate ones, closed for filling.
  std::vector<Contour> finish();
  /// Ends the last subpath and returns all non-degenerate ones as drawn (open ones stay open).
  std::vector<Subpath> finishSubpaths();

  const Point2& current() const { return current_; }
  const Point2& start() const { return start_; }

 private:
  void endSubpath(bool closed);

  PointBudget& budget_;
  std::vector<Subpath> subpaths_;
  Contour open_;
  Point2 start_ = Point2::Zero();
  Point2 current_ = Point2::Zero();
};

}  // namespace io_detail
}  // namespace vicc_glyphs
