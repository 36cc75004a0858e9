#pragma once
// The Diffusion Curve Image (DCI) of Orzan et al. 2008 (thesis 2.6): the representation every
// part of vicc_glyphs shares (formats, B-spline toolkit, renderer, PACEMOD).
//
// Conventions (all code in this package follows them; importers convert to them):
// - Image coordinates in pixels: x to the right, y down, origin at the top-left corner of the
//   top-left pixel (pixel (i, j) covers [i, i+1) x [j, j+1), its centre is (i+0.5, j+0.5)).
// - A curve is a chain of K cubic Bezier segments given by 3K+1 control points; segment k uses
//   points 3k .. 3k+3.
// - Curve parameter s in [0, K]: floor(s) is the segment, s - floor(s) the local Bezier
//   parameter. Colour and blur points are placed at such parameters (Orzan's XML globalID / 10).
// - "Left" is the side on the left when walking along the curve as seen on screen: for the
//   tangent (dx, dy) the left normal is (dy, -dx) in the y-down image frame.
// - Colours are linear RGB in [0, 1].

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace vicc_glyphs {

using Point2 = Eigen::Vector2d;
using Color = Eigen::Vector3d;

/// The z component of the 3-D cross product of `a` and `b`: the sine of the angle from a to b
/// times both lengths (on screen, y down: positive when b points clockwise from a).
inline double cross(const Point2& a, const Point2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// A colour constraint at curve parameter `position` (in [0, K]).
struct ColorPoint {
  double position = 0.0;
  Color rgb = Color::Zero();
};

/// A blur constraint (Orzan's blur points): Gaussian blur sigma in pixels at `position`.
struct BlurPoint {
  double position = 0.0;
  double sigma = 0.0;
};

/// One diffusion curve: geometry plus colour constraints on each side. A side with
/// `emits == false` is a diffusion barrier there: it blocks diffusion but adds no colour.
struct DiffusionCurve {
  std::vector<Point2> control_points;    ///< 3K+1 points
  std::vector<ColorPoint> left_colors;   ///< sorted by position
  std::vector<ColorPoint> right_colors;  ///< sorted by position
  std::vector<BlurPoint> blur_points;    ///< sorted by position
  bool left_emits = true;
  bool right_emits = true;

  /// Number of cubic segments K (0 when the point count is not 3K+1 with K >= 1).
  int segmentCount() const;
  /// Point and first derivative (d/ds) at curve parameter s, clamped to [0, K].
  Point2 pointAt(double s) const;
  Point2 derivativeAt(double s) const;
  /// Linear interpolation of the colour points (constant beyond the ends). Black if empty.
  Color leftColorAt(double s) const;
  Color rightColorAt(double s) const;
  /// Blur sigma interpolated like the colours; 0 if there are no blur points.
  double blurAt(double s) const;
};

/// A whole image: its size and curves.
struct DiffusionCurveImage {
  int width = 0;
  int height = 0;
  std::vector<DiffusionCurve> curves;
};

/// Linear interpolation of sorted colour points at parameter s (shared by both sides).
Color interpolateColor(const std::vector<ColorPoint>& points, double s);

/// Colours within this of each other (per channel) count as one: the importers' 8-bit colours
/// / 255, with round-off.
constexpr double kSameColorTolerance = 0.6 / 255.0;

/// The colour that covers most of one side of a curve: colour points are piecewise linear in
/// their position, and each interval counts for the colours at its ends, half each (a single
/// point counts alone). Empty for no points. Where a side carries a neighbour's colour along a
/// shared stretch, this is the colour of the rest (the surroundings), not a mix of both.
std::optional<Color> dominantColor(const std::vector<ColorPoint>& points);

/// Checks the structural invariants (3K+1 points, finite coordinates and colours, colours in
/// [0, 1], positions within [0, K] and sorted, positive image size). Returns an empty string
/// when valid, otherwise a human-readable reason naming the curve index.
std::string validate(const DiffusionCurveImage& image);

/// Uniformly scales geometry (and blur sigmas) so the image becomes `size` pixels wide,
/// keeping the aspect ratio; used to render at a chosen resolution.
DiffusionCurveImage scaledToWidth(const DiffusionCurveImage& image, int size);

}  // namespace vicc_glyphs
