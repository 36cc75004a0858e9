#include "vicc_glyphs/pacemod/contour_teeth.hpp"

#include "vicc_glyphs/pacemod/contour_corners.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

// Unit direction at the anchor points[from] along its segment after (`step` +1) or before (-1)
// it; zero if that segment has no length.
Point2 directionAt(const std::vector<Point2>& points, int from, int step) {
  return controlPolygonDirection(points, from, step, 3);
}

double polygonLength(const std::vector<Point2>& points, int segment) {
  double length = 0.0;
  for (int k = 0; k < 3; ++k) {
    length += (points[3 * segment + k + 1] - points[3 * segment + k]).norm();
  }
  return length;
}

// Segment j (0 < j < K - 1) is a tooth: shorter than kOneCornerPx between two sharp joins, its
// neighbours not. A chain of short segments that turn by a few degrees each (a finely
// flattened arc) is a shape, not a tooth: taken out one by one it would shrink to nothing.
bool isTooth(const std::vector<Point2>& points, int j, double smooth_cosine) {
  if (polygonLength(points, j) >= kOneCornerPx || polygonLength(points, j - 1) < kOneCornerPx ||
      polygonLength(points, j + 1) < kOneCornerPx) {
    return false;
  }
  const int a = 3 * j, b = 3 * j + 3;
  const Point2 before = directionAt(points, a, -1), after = directionAt(points, b, 1);
  const Point2 leaving = directionAt(points, a, 1), arriving = directionAt(points, b, -1);
  if (before.isZero() || after.isZero() || leaving.isZero() || arriving.isZero()) return false;
  return before.dot(leaving) < smooth_cosine && arriving.dot(after) < smooth_cosine;
}

// Positions on segment j go to its start, later ones back by one segment.
template <typename Points>
void dropSegment(Points& points, int j) {
  for (auto& point : points) {
    if (point.position > j + 1) {
      point.position -= 1.0;
    } else if (point.position > j) {
      point.position = j;
    }
  }
}

}  // namespace

DiffusionCurve withoutTeeth(const DiffusionCurve& curve) {
  const double smooth_cosine = smoothJoinCosine();
  std::vector<int> teeth;  // found on the curve as it is: a tooth's neighbours are none
  for (int j = 1; j + 1 < curve.segmentCount(); ++j) {
    if (isTooth(curve.control_points, j, smooth_cosine)) teeth.push_back(j);
  }
  DiffusionCurve result = curve;
  std::vector<Point2>& points = result.control_points;
  // From the end, so that the teeth still to be removed keep their indices.
  for (auto j = teeth.rbegin(); j != teeth.rend(); ++j) {
    const int a = 3 * *j, b = 3 * *j + 3;
    const Point2 middle = 0.5 * (points[a] + points[b]);
    points[a - 1] += middle - points[a];
    points[b + 1] += middle - points[b];
    points[a] = middle;
    points.erase(points.begin() + a + 1, points.begin() + b + 1);
    dropSegment(result.left_colors, *j);
    dropSegment(result.right_colors, *j);
    dropSegment(result.blur_points, *j);
  }
  return result;
}

}  // namespace pacemod
}  // namespace vicc_glyphs
