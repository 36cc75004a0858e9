#include "vicc_glyphs/bspline/frenet_frame.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace vicc_glyphs {
namespace bspline {
namespace {

Point2 leftOf(const Point2& v) { return Point2(v.y(), -v.x()); }

Point2 firstDerivativeOrThrow(const BSplineCurve& curve, double u) {
  const Point2 velocity = curve.derivativeAt(u, 1);
  if (!(velocity.norm() > 0.0)) {
    throw std::invalid_argument("frenet frame: the first derivative vanishes at u = " +
                                std::to_string(u));
  }
  return velocity;
}

}  // namespace

double signedCurvatureAt(const BSplineCurve& curve, double u) {
  const Point2 first = firstDerivativeOrThrow(curve, u);
  const Point2 second = curve.derivativeAt(u, 2);
  const double speed = first.norm();
  // Projecting s'' on the left normal gives the sign convention of the y-down frame directly.
  return second.dot(leftOf(first)) / (speed * speed * speed);
}

Point2 leftNormalAt(const BSplineCurve& curve, double u) {
  return leftOf(firstDerivativeOrThrow(curve, u)).normalized();
}

FrenetFrame frenetFrameAt(const BSplineCurve& curve, double u) {
  FrenetFrame frame;
  frame.position = curve.pointAt(u);
  frame.tangent = firstDerivativeOrThrow(curve, u).normalized();
  frame.curvature = signedCurvatureAt(curve, u);
  const Point2 left = leftOf(frame.tangent);
  frame.normal = frame.curvature < 0.0 ? Point2(-left) : left;
  return frame;
}

double signedArea(const BSplineCurve& curve, int samples_per_span) {
  if (samples_per_span < 1) throw std::invalid_argument("signedArea: need >= 1 sample per span");
  const std::vector<double> breaks = curve.breakpoints();
  std::vector<Point2> polygon;
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
    for (int i = 0; i < samples_per_span; ++i) {
      const double w = static_cast<double>(i) / samples_per_span;
      polygon.push_back(curve.pointAt((1.0 - w) * breaks[k] + w * breaks[k + 1]));
    }
  }
  polygon.push_back(curve.pointAt(curve.domainEnd()));
  double twice_area = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Point2& a = polygon[i];
    const Point2& b = polygon[(i + 1) % polygon.size()];
    twice_area += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * twice_area;
}

Point2 inwardNormalAt(const BSplineCurve& curve, double u) {
  return inwardNormalAt(curve, u, signedArea(curve));
}

Point2 inwardNormalAt(const BSplineCurve& curve, double u, double signed_area) {
  if (!(signed_area != 0.0) || !std::isfinite(signed_area)) {
    throw std::invalid_argument("inwardNormalAt: the curve encloses no area");
  }
  const Point2 left = leftNormalAt(curve, u);
  return signed_area > 0.0 ? Point2(-left) : left;
}

}  // namespace bspline
}  // namespace vicc_glyphs
