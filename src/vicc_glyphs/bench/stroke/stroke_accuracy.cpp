#include "stroke_accuracy.hpp"

#include <algorithm>
#include <cmath>

namespace vicc_glyphs {
namespace io_detail {
namespace stroke_accuracy {

const IntegerFrame& caseFrame() {
  static const IntegerFrame frame(kFrameSize, kFrameSize);
  return frame;
}

Subpath cubicSubpath(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  return {{a, b, c, d}, false};
}

Subpath circleSubpath(const Point2& c, double r) {
  const double k = 0.5522847498 * r;
  return {
      {c + Point2(r, 0), c + Point2(r, k), c + Point2(k, r), c + Point2(0, r), c + Point2(-k, r),
       c + Point2(-r, k), c + Point2(-r, 0), c + Point2(-r, -k), c + Point2(-k, -r),
       c + Point2(0, -r), c + Point2(k, -r), c + Point2(r, -k), c + Point2(r, 0)},
      true};
}

StrokeGeometry roundStroke(double width) {
  StrokeGeometry stroke;
  stroke.width = width;
  stroke.cap = LineCap::kRound;
  stroke.join = LineJoin::kRound;
  return stroke;
}

std::vector<AccuracyCase> accuracyCases() {
  const auto arc = cubicSubpath(Point2(40, 200), Point2(80, 60), Point2(176, 60), Point2(216, 200));
  return {
      {"arc", {arc}, 16},
      {"s-curve",
       {cubicSubpath(Point2(40, 128), Point2(120, 0), Point2(136, 256), Point2(216, 128))},
       16},
      {"u-turn",
       {cubicSubpath(Point2(40, 100), Point2(240, 100), Point2(240, 140), Point2(40, 140))},
       16},
      {"loop",
       {cubicSubpath(Point2(50, 200), Point2(250, 40), Point2(6, 40), Point2(206, 200))},
       16},
      {"cusp",
       {cubicSubpath(Point2(40, 200), Point2(216, 24), Point2(40, 24), Point2(216, 200))},
       16},
      {"circle", {circleSubpath(Point2(128, 128), 80)}, 16},
      {"arc-wide", {arc}, 48},
      // A 2-unit Feather stroke at 256 px.
      {"icon-arc",
       {cubicSubpath(Point2(60, 150), Point2(60, 100), Point2(100, 60), Point2(150, 60))},
       21.3},
  };
}

double distanceToChain(const Contour& chain, const Point2& p) {
  double best = 1e300;
  for (std::size_t k = 0; k + 3 < chain.size(); k += 3) {
    const Point2* b = &chain[k];
    auto at = [&](double t) {
      const double u = 1 - t;
      return u * u * u * b[0] + 3 * u * u * t * b[1] + 3 * u * t * t * b[2] + t * t * t * b[3];
    };
    auto d1 = [&](double t) {
      const double u = 1 - t;
      return 3 * (u * u * (b[1] - b[0]) + 2 * u * t * (b[2] - b[1]) + t * t * (b[3] - b[2]));
    };
    constexpr int kSamples = 4000;
    double t_best = 0.0, d_best = 1e300;
    for (int i = 0; i <= kSamples; ++i) {
      const double t = static_cast<double>(i) / kSamples, d = (at(t) - p).norm();
      if (d < d_best) d_best = d, t_best = t;
    }
    double t = t_best;
    for (int i = 0; i < 8; ++i) {  // minimise |at(t) - p| with a secant-free Gauss-Newton step
      const Point2 g = d1(t);
      if (g.squaredNorm() == 0.0) break;
      t = std::clamp(t - (at(t) - p).dot(g) / g.squaredNorm(), 0.0, 1.0);
    }
    best = std::min({best, d_best, (at(t) - p).norm()});
  }
  return best;
}

Deviation deviation(const Paths& area, const IntegerFrame& frame,
                    const std::vector<Subpath>& subpaths, double half) {
  Deviation d;
  for (const Path& path : area) {
    for (const IntPoint& q : path) {
      const Point2 p = frame.toPixel(q);
      double distance = 1e300;
      for (const Subpath& s : subpaths) distance = std::min(distance, distanceToChain(s.points, p));
      const double e = std::abs(distance - half);
      d.max = std::max(d.max, e), d.mean += e, ++d.vertices;
    }
  }
  d.mean /= std::max<std::size_t>(d.vertices, 1);
  return d;
}

}  // namespace stroke_accuracy
}  // namespace io_detail
}  // namespace vicc_glyphs
