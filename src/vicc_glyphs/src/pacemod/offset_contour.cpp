#include "vicc_glyphs/pacemod/offset_contour.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "vicc_glyphs/bspline/bezier_conversion.hpp"
#include "vicc_glyphs/bspline/fitting.hpp"
#include "vicc_glyphs/bspline/fowler_bartels.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

constexpr int kMaxGrid = 2048;
constexpr int kSubpixelBits = 8;

using Grid = detail::IsolineGrid;

Grid gridAround(const Polyline& contour, double margin, double scale) {
  Point2 low = contour.front(), high = contour.front();
  for (const Point2& p : contour) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  low -= Point2::Constant(margin);
  high += Point2::Constant(margin);
  const double extent = std::max(high.x() - low.x(), high.y() - low.y());
  scale = std::min(scale, kMaxGrid / std::max(extent, 1e-9));
  return {low, scale,
          cv::Size(static_cast<int>(std::ceil((high.x() - low.x()) * scale)) + 1,
                   static_cast<int>(std::ceil((high.y() - low.y()) * scale)) + 1)};
}

std::vector<cv::Point> gridPolygon(const Polyline& contour, const Grid& grid) {
  std::vector<cv::Point> polygon;
  const double unit = 1 << kSubpixelBits;
  for (const Point2& p : contour) {
    const Point2 g = (p - grid.origin) * grid.scale - Point2::Constant(0.5);
    polygon.emplace_back(static_cast<int>(std::lround(g.x() * unit)),
                         static_cast<int>(std::lround(g.y() * unit)));
  }
  return polygon;
}

// The signed distance to the contour in grid pixels on the side that decides whether a pixel
// lies within an offset of that sign, 0 on the other side: outside (`outward`: every inside
// pixel is within an outward offset, an outside one by its distance to the inside) or inside
// (no outside pixel is within an inward offset or 0, an inside one by its distance to the
// outside, negative). Each side's distance transform measures to the nearest pixel centre of the
// other side, so half a pixel is taken off to put the zero level on the boundary between them.
cv::Mat sideField(const Polyline& contour, const Grid& grid, bool outward) {
  cv::Mat inside = cv::Mat::zeros(grid.size, CV_8U);
  cv::fillPoly(inside, std::vector<std::vector<cv::Point>>{gridPolygon(contour, grid)}, 255,
               cv::LINE_8, kSubpixelBits);
  cv::Mat field;
  if (outward) {
    cv::distanceTransform(255 - inside, field, cv::DIST_L2, cv::DIST_MASK_PRECISE);
    cv::subtract(field, 0.5, field, inside == 0);
  } else {
    cv::Mat to_outside;
    cv::distanceTransform(inside, to_outside, cv::DIST_L2, cv::DIST_MASK_PRECISE);
    field = -to_outside;
    cv::add(field, 0.5, field, inside);
  }
  return field;
}

// The region's isoline traced on `grid` (see offsetIsoline).
Polyline traceLargest(const cv::Mat& region, const Grid& grid, const Polyline& contour) {
  std::vector<std::vector<cv::Point>> traced;
  cv::findContours(region, traced, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
  const auto largest =
      std::max_element(traced.begin(), traced.end(), [](const auto& a, const auto& b) {
        return std::abs(cv::contourArea(a)) < std::abs(cv::contourArea(b));
      });
  if (largest == traced.end() || largest->size() < 8) return {};
  Polyline result;
  for (const cv::Point& p : *largest) {
    result.push_back(grid.origin + (Point2(p.x, p.y) + Point2::Constant(0.5)) / grid.scale);
  }
  result.push_back(result.front());
  if ((polylineArea(result) > 0.0) != (polylineArea(contour) > 0.0)) {
    std::reverse(result.begin(), result.end());
  }
  return result;
}

}  // namespace

Polyline offsetIsoline(const Polyline& contour, double offset, double grid_scale) {
  return offsetIsolineAvoiding(contour, offset, {}, 0.0, grid_scale);
}

Polyline offsetIsolineAvoiding(const Polyline& contour, double offset,
                               const std::vector<Polyline>& obstacles, double clearance,
                               double grid_scale, bool* limited) {
  if (limited) *limited = false;
  if (contour.size() < 4 || !std::isfinite(offset)) return {};
  const Grid grid = gridAround(contour, std::max(offset, 0.0) + 3.0, grid_scale);
  cv::Mat region = sideField(contour, grid, offset > 0.0) < offset * grid.scale;
  std::vector<std::vector<cv::Point>> polygons;
  for (const Polyline& obstacle : obstacles) {
    if (obstacle.size() >= 4) polygons.push_back(gridPolygon(obstacle, grid));
  }
  if (!polygons.empty()) {
    cv::Mat free = cv::Mat(grid.size, CV_8U, cv::Scalar(255));
    for (const auto& polygon : polygons) {  // one by one: overlapping obstacles stay filled
      cv::fillPoly(free, std::vector<std::vector<cv::Point>>{polygon}, 0, cv::LINE_8,
                   kSubpixelBits);
    }
    cv::Mat to_obstacle;
    cv::distanceTransform(free, to_obstacle, cv::DIST_L2, cv::DIST_MASK_PRECISE);
    const int before = cv::countNonZero(region);
    region = region & (to_obstacle > clearance * grid.scale);
    if (limited) *limited = cv::countNonZero(region) < before;
  }
  return traceLargest(region, grid, contour);
}

InsideDistance::InsideDistance(const Polyline& contour, double grid_scale) : contour_(contour) {
  if (contour.size() < 4) return;
  grid_ = gridAround(contour, 3.0, grid_scale);  // offsetIsolineAvoiding's grid for offset <= 0
  field_ = sideField(contour, grid_, false);
}

Polyline InsideDistance::isoline(double offset) const {
  if (offset > 0.0) throw std::invalid_argument("InsideDistance::isoline: an offset > 0");
  if (field_.empty() || !std::isfinite(offset)) return {};
  return traceLargest(field_ < offset * grid_.scale, grid_, contour_);
}

std::vector<Point2> closedBezierFit(const Polyline& line, double knot_spacing) {
  if (line.size() < 5) throw std::invalid_argument("closedBezierFit: need at least 4 points");
  double length = 0.0;
  for (std::size_t i = 0; i + 1 < line.size(); ++i) length += (line[i + 1] - line[i]).norm();
  const int spans = std::clamp(static_cast<int>(std::lround(length / knot_spacing)), 4,
                               static_cast<int>(line.size()) / 2);
  const std::vector<double> parameters = bspline::chordLengthParameters(line, 0.0, 1.0);
  const std::vector<double> knots =
      bspline::BSplineCurve::clampedUniformKnots(3, spans + 3, 0.0, 1.0);
  // Banded normal equations: tens of points per span determine the curve well, and a sparse QR
  // of a traced isoline (thousands of points) cost as much as the distance transform.
  const bspline::CubicLeastSquares solver(
      bspline::BSplineCurve(3, knots, std::vector<Point2>(knots.size() - 4, Point2::Zero())),
      parameters);
  Eigen::MatrixX2d targets(static_cast<Eigen::Index>(line.size()), 2);
  for (std::size_t i = 0; i < line.size(); ++i) targets.row(static_cast<Eigen::Index>(i)) = line[i];
  bspline::BSplineCurve fit(3, knots, solver.solvePoints(targets));
  // Close it exactly with equal end tangents (the fit leaves both ends free).
  const Point2 start = 0.5 * (fit.pointAt(0.0) + fit.pointAt(1.0));
  const Point2 tangent = 0.5 * (fit.derivativeAt(0.0) + fit.derivativeAt(1.0));
  fit = bspline::fowlerBartelsModify(
      fit, {{0.0, start, 0}, {1.0, start, 0}, {0.0, tangent, 1}, {1.0, tangent, 1}});
  return bspline::bsplineToBezierChain(fit).control_points;
}

}  // namespace pacemod
}  // namespace vicc_glyphs
