#pragma once
// One cubic Bezier segment by its four control points, with the derivatives the importer's
// curve fitting (bezier_refit.cpp) and stroke outlines (curve_stroke.cpp) evaluate.

#include <array>

#include "vicc_glyphs/dci/diffusion_curve.hpp"

namespace vicc_glyphs {
namespace io_detail {

struct CubicBezier {
  std::array<Point2, 4> b;

  Point2 at(double t) const {
    const double u = 1.0 - t;
    return u * u * u * b[0] + 3.0 * u * u * t * b[1] + 3.0 * u * t * t * b[2] + t * t * t * b[3];
  }
  Point2 d1(double t) const {
    const double u = 1.0 - t;
    return 3.0 * (u * u * (b[1] - b[0]) + 2.0 * u * t * (b[2] - b[1]) + t * t * (b[3] - b[2]));
  }
  Point2 d2(double t) const {
    return 6.0 * ((1.0 - t) * (b[2] - 2.0 * b[1] + b[0]) + t * (b[3] - 2.0 * b[2] + b[1]));
  }
  Point2 d3() const { return 6.0 * (b[3] - 3.0 * b[2] + 3.0 * b[1] - b[0]); }
};

}  // namespace io_detail
}  // namespace vicc_glyphs
