#include "svg_arc.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace vicc_glyphs {
namespace io_detail {
namespace {

double angleBetween(const Point2& u, const Point2& v) { return std::atan2(cross(u, v), u.dot(v)); }

}  // namespace

std::vector<Point2> arcToCubics(const Point2& from, double rx, double ry, double x_axis_degrees,
                                bool large_arc, bool sweep, const Point2& to) {
  rx = std::abs(rx);
  ry = std::abs(ry);
  if (from == to) return {};
  if (rx < 1e-12 || ry < 1e-12) {
    return {from + (to - from) / 3.0, from + 2.0 * (to - from) / 3.0, to};
  }
  const double phi = x_axis_degrees * M_PI / 180.0;
  const Eigen::Rotation2Dd rotation(phi);
  // Step 1: the midpoint difference in the ellipse's own axes.
  const Eigen::Vector2d p = rotation.inverse() * ((from - to) / 2.0);
  // Too small radii are scaled up until the arc just fits (F.6.6).
  const double lambda = (p.x() * p.x()) / (rx * rx) + (p.y() * p.y()) / (ry * ry);
  if (lambda > 1.0) {
    rx *= std::sqrt(lambda);
    ry *= std::sqrt(lambda);
  }
  // Step 2: the centre in the ellipse's axes.
  const double numerator = rx * rx * ry * ry - rx * rx * p.y() * p.y() - ry * ry * p.x() * p.x();
  const double denominator = rx * rx * p.y() * p.y() + ry * ry * p.x() * p.x();
  double factor = denominator > 0.0 ? std::sqrt(std::max(0.0, numerator / denominator)) : 0.0;
  if (large_arc == sweep) factor = -factor;
  const Eigen::Vector2d centre_local(factor * rx * p.y() / ry, -factor * ry * p.x() / rx);
  const Eigen::Vector2d centre = rotation * centre_local + (from + to) / 2.0;
  // Step 3: start angle and sweep.
  const Eigen::Vector2d u((p.x() - centre_local.x()) / rx, (p.y() - centre_local.y()) / ry);
  const Eigen::Vector2d v((-p.x() - centre_local.x()) / rx, (-p.y() - centre_local.y()) / ry);
  const double theta = angleBetween(Eigen::Vector2d(1, 0), u);
  double delta = angleBetween(u, v);
  if (!sweep && delta > 0) delta -= 2.0 * M_PI;
  if (sweep && delta < 0) delta += 2.0 * M_PI;

  return centredArcToCubics(centre, rx, ry, phi, theta, delta, from, to);
}

std::vector<Point2> centredArcToCubics(const Point2& centre, double rx, double ry,
                                       double rotation_radians, double theta, double delta,
                                       const Point2& from, const Point2& to) {
  const Eigen::Rotation2Dd rotation(rotation_radians);
  // Each piece spans at most 90 degrees; its handles have length k = 4/3 tan(piece/4).
  const int pieces = std::max(1, static_cast<int>(std::ceil(std::abs(delta) / (M_PI / 2) - 1e-9)));
  const double step = delta / pieces;
  const double k = 4.0 / 3.0 * std::tan(step / 4.0);
  auto onEllipse = [&](double angle) {
    return Point2(rotation * Eigen::Vector2d(rx * std::cos(angle), ry * std::sin(angle)) + centre);
  };
  auto tangent = [&](double angle) {
    return Point2(rotation * Eigen::Vector2d(-rx * std::sin(angle), ry * std::cos(angle)));
  };
  std::vector<Point2> points;
  double angle = theta;
  Point2 start = from;
  for (int i = 0; i < pieces; ++i) {
    const double next = angle + step;
    const Point2 end = i + 1 == pieces ? to : onEllipse(next);
    points.push_back(start + k * tangent(angle));
    points.push_back(end - k * tangent(next));
    points.push_back(end);
    start = end;
    angle = next;
  }
  return points;
}

}  // namespace io_detail
}  // namespace vicc_glyphs
