#include "sample_images.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace vicc_glyphs {

DiffusionCurve lineCurve(const Point2& from, const Point2& to, const Color& left,
                         const Color& right) {
  DiffusionCurve curve;
  curve.control_points = {from, from + (to - from) / 3.0, from + 2.0 * (to - from) / 3.0, to};
  curve.left_colors = {{0.0, left}};
  curve.right_colors = {{0.0, right}};
  return curve;
}

DiffusionCurve polygonCurve(const std::vector<Point2>& corners, const Color& left,
                            const Color& right) {
  DiffusionCurve curve;
  curve.control_points = {corners.front()};
  for (size_t k = 1; k <= corners.size(); ++k) {
    const Point2 from = corners[k - 1], to = corners[k % corners.size()];
    curve.control_points.insert(curve.control_points.end(),
                                {from + (to - from) / 3.0, from + 2.0 * (to - from) / 3.0, to});
  }
  curve.left_colors = {{0.0, left}};
  curve.right_colors = {{0.0, right}};
  return curve;
}

DiffusionCurve circleCurve(const Point2& centre, double radius, const Color& inside,
                           const Color& outside) {
  constexpr double kappa = 0.5522847498;  // cubic approximation of a quarter circle
  const double r = radius, k = kappa * radius;
  const Point2 c = centre;
  DiffusionCurve curve;
  // Angles 0, 90, 180, 270 degrees in the y-down frame: clockwise as seen on screen.
  curve.control_points = {c + Point2(r, 0),  c + Point2(r, k),   c + Point2(k, r),
                          c + Point2(0, r),  c + Point2(-k, r),  c + Point2(-r, k),
                          c + Point2(-r, 0), c + Point2(-r, -k), c + Point2(-k, -r),
                          c + Point2(0, -r), c + Point2(k, -r),  c + Point2(r, -k),
                          c + Point2(r, 0)};
  curve.left_colors = {{0.0, outside}};
  curve.right_colors = {{0.0, inside}};
  return curve;
}

DiffusionCurveImage twoColourLineImage(int width, int height) {
  DiffusionCurveImage image{width, height, {}};
  const double x = 0.45 * width;
  image.curves.push_back(lineCurve({x, height + 2.0}, {x, -2.0}, Color(1, 0, 0), Color(0, 0, 1)));
  return image;
}

DiffusionCurveImage circleImage(int width, int height) {
  DiffusionCurveImage image{width, height, {}};
  image.curves.push_back(circleCurve({0.5 * width, 0.5 * height}, 0.3 * std::min(width, height),
                                     Color(1.0, 0.6, 0.1), Color(0.05, 0.1, 0.4)));
  return image;
}

DiffusionCurveImage gradientCircleImage(int width, int height) {
  DiffusionCurveImage image = circleImage(width, height);
  image.curves.front().right_colors = {{0.0, Color(1, 0, 0)},
                                       {1.0, Color(0, 1, 0)},
                                       {2.0, Color(0, 0, 1)},
                                       {3.0, Color(1, 1, 0)},
                                       {4.0, Color(1, 0, 0)}};
  return image;
}

DiffusionCurveImage barrierImage(int width, int height) {
  DiffusionCurveImage image{width, height, {}};
  DiffusionCurve barrier =
      lineCurve({0.5 * width, -2.0}, {0.5 * width, height + 2.0}, Color::Zero(), Color::Zero());
  barrier.left_emits = false;
  barrier.right_emits = false;
  image.curves.push_back(barrier);
  const double r = 0.1 * std::min(width, height);
  image.curves.push_back(
      circleCurve({0.25 * width, 0.5 * height}, r, Color(1, 0, 0), Color(1, 0, 0)));
  image.curves.push_back(
      circleCurve({0.75 * width, 0.5 * height}, r, Color(0, 0, 1), Color(0, 0, 1)));
  return image;
}

DiffusionCurveImage iconLikeImage(int width, int height) {
  DiffusionCurveImage image{width, height, {}};
  const double w = width, h = height;
  DiffusionCurve wave;
  wave.control_points = {{0.05 * w, 0.7 * h}, {0.25 * w, 0.4 * h}, {0.4 * w, 0.95 * h},
                         {0.55 * w, 0.7 * h}, {0.7 * w, 0.45 * h}, {0.85 * w, 0.9 * h},
                         {0.97 * w, 0.6 * h}};
  wave.left_colors = {{0.0, Color(0.9, 0.2, 0.1)}, {2.0, Color(1.0, 0.9, 0.2)}};
  wave.right_colors = {{0.0, Color(0.1, 0.3, 0.8)}, {1.0, Color(0.2, 0.8, 0.4)}};
  image.curves.push_back(wave);
  image.curves.push_back(circleCurve({0.3 * w, 0.3 * h}, 0.18 * std::min(w, h),
                                     Color(1.0, 1.0, 1.0), Color(0.3, 0.3, 0.35)));
  image.curves.push_back(circleCurve({0.3 * w, 0.3 * h}, 0.08 * std::min(w, h),
                                     Color(0.8, 0.1, 0.5), Color(0.9, 0.9, 0.95)));
  DiffusionCurve barrier =
      lineCurve({0.6 * w, 0.05 * h}, {0.85 * w, 0.4 * h}, Color::Zero(), Color::Zero());
  barrier.left_emits = false;
  barrier.right_emits = false;
  image.curves.push_back(barrier);
  image.curves.push_back(
      lineCurve({0.75 * w, 0.05 * h}, {0.95 * w, 0.2 * h}, Color(0, 0.5, 0.5), Color(1, 1, 1)));
  return image;
}

DiffusionCurveImage zigzagImage(int size, int teeth, double inner, double outer) {
  DiffusionCurveImage image{size, size, {}};
  const Point2 centre(size / 2.0, size / 2.0);
  std::vector<Point2> corners;
  for (int k = 0; k < 2 * teeth; ++k) {
    const double angle = M_PI * k / teeth, radius = size * (k % 2 ? outer : inner);
    corners.push_back(centre + radius * Point2(std::cos(angle), std::sin(angle)));
  }
  // Angles grow clockwise on screen (y down): the inside is the right side.
  image.curves.push_back(polygonCurve(corners, Color(0.05, 0.1, 0.4), Color(1.0, 0.6, 0.1)));
  return image;
}

}  // namespace vicc_glyphs
