#pragma once
// Small DCIs with known answers for the renderer tests and the bench.

#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"

namespace vicc_glyphs {

/// A straight one-segment curve from `from` to `to` with constant side colours.
DiffusionCurve lineCurve(const Point2& from, const Point2& to, const Color& left,
                         const Color& right);
/// A closed polygon through `corners` (straight cubic segments, back to the first corner).
DiffusionCurve polygonCurve(const std::vector<Point2>& corners, const Color& left,
                            const Color& right);
/// A closed circle of four Beziers, clockwise on screen, so its inside is its right side.
DiffusionCurve circleCurve(const Point2& centre, double radius, const Color& inside,
                           const Color& outside);

/// A vertical line through the whole image at x = 0.45 * width, drawn upwards: red on its left
/// (screen left), blue on its right.
DiffusionCurveImage twoColourLineImage(int width, int height);
/// A circle with an orange inside and a dark blue outside.
DiffusionCurveImage circleImage(int width, int height);
/// A circle whose inside colour runs red, green, blue, yellow around it: a smooth gradient.
DiffusionCurveImage gradientCircleImage(int width, int height);
/// A full-height vertical barrier at the middle, a red circle left of it, a blue one right.
DiffusionCurveImage barrierImage(int width, int height);
/// Several curves with colour gradients along them, a partial barrier and nested circles.
DiffusionCurveImage iconLikeImage(int width, int height);
/// A closed zigzag of straight segments round the centre of a size x size image: a star of
/// `teeth` sharp tips, alternately at `inner` and `outer` times the size from the centre;
/// clockwise on screen, orange inside (its right side), dark blue outside.
DiffusionCurveImage zigzagImage(int size, int teeth, double inner, double outer);

}  // namespace vicc_glyphs
