#pragma once
// Test shapes: a closed polygon as a chain of straight cubic Beziers.

#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"

namespace vicc_glyphs::test {

/// The Bezier control points (3K + 1) of the closed polygon through `corners`: each side a
/// straight cubic with its inner control points at a third and two thirds of it.
inline std::vector<Point2> closedStraightChain(std::vector<Point2> corners) {
  corners.push_back(corners.front());
  std::vector<Point2> points{corners.front()};
  for (std::size_t k = 0; k + 1 < corners.size(); ++k) {
    const Point2 a = corners[k], b = corners[k + 1];
    points.insert(points.end(), {a + (b - a) / 3.0, a + 2.0 * (b - a) / 3.0, b});
  }
  return points;
}

}  // namespace vicc_glyphs::test
