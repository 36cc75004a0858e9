#include "boundary_twins.hpp"

#include <algorithm>
#include <optional>

#include "vicc_glyphs/pacemod/polyline.hpp"

namespace vicc_glyphs::design {
namespace {

using pacemod::Polyline;

// Colours match within the 8-bit quantisation of the importers.
constexpr double kColorTolerance = 0.6 / 255.0;
// Twins come from the same polygon refit on either side: they agree to the fit tolerance.
constexpr double kCoincidencePx = 0.25;
constexpr double kSigmaTolerance = 1e-6;

std::optional<Color> singleColor(const std::vector<ColorPoint>& points) {
  if (points.empty()) return std::nullopt;
  for (const ColorPoint& p : points) {
    if ((p.rgb - points.front().rgb).cwiseAbs().maxCoeff() > kColorTolerance) return std::nullopt;
  }
  return points.front().rgb;
}

bool sameColor(const std::optional<Color>& a, const std::optional<Color>& b) {
  return a && b && (*a - *b).cwiseAbs().maxCoeff() <= kColorTolerance;
}

bool sameBlur(const std::vector<BlurPoint>& a, const std::vector<BlurPoint>& b) {
  const auto single = [](const std::vector<BlurPoint>& points, double sigma) {
    return std::all_of(points.begin(), points.end(), [sigma](const BlurPoint& p) {
      return std::abs(p.sigma - sigma) <= kSigmaTolerance;
    });
  };
  if (a.empty() || b.empty()) return a.empty() && b.empty();
  return single(a, a.front().sigma) && single(b, a.front().sigma);
}

bool closed(const Polyline& line) {
  return line.size() >= 4 && (line.front() - line.back()).norm() <= 1e-6;
}

// Every sample of `a` lies on `b` (the samples are dense: 8 per cubic).
bool liesOn(const Polyline& a, const Polyline& b) {
  return std::all_of(a.begin(), a.end(), [&b](const Point2& p) {
    return pacemod::distanceToPolyline(p, b) <= kCoincidencePx;
  });
}

struct Boundary {
  Polyline line;
  double signed_area = 0.0;
  std::optional<Color> left, right;
};

// `hole` is the copy of `outline`: the same closed line run the other way round, the colours
// swapped, and the enclosed region on its right (positive area: clockwise on screen).
bool isTwinHole(const Boundary& hole, const DiffusionCurve& hole_curve, const Boundary& outline,
                const DiffusionCurve& outline_curve) {
  return closed(hole.line) && closed(outline.line) && hole.signed_area > 0.0 &&
         outline.signed_area < 0.0 && sameColor(hole.left, outline.right) &&
         sameColor(hole.right, outline.left) &&
         sameBlur(hole_curve.blur_points, outline_curve.blur_points) &&
         liesOn(hole.line, outline.line) && liesOn(outline.line, hole.line);
}

}  // namespace

int removeBoundaryTwins(DiffusionCurveImage& image) {
  std::vector<Boundary> boundaries;
  for (const DiffusionCurve& curve : image.curves) {
    Boundary b;
    b.line = pacemod::sampleCurve(curve, 8);
    b.signed_area = pacemod::polylineArea(b.line);
    b.left = singleColor(curve.left_colors);
    b.right = singleColor(curve.right_colors);
    boundaries.push_back(std::move(b));
  }
  std::vector<bool> remove(image.curves.size(), false);
  for (size_t i = 0; i < image.curves.size(); ++i) {
    for (size_t j = 0; j < image.curves.size() && !remove[i]; ++j) {
      remove[i] = j != i && !remove[j] &&
                  isTwinHole(boundaries[i], image.curves[i], boundaries[j], image.curves[j]);
    }
  }
  std::vector<DiffusionCurve> kept;
  for (size_t i = 0; i < image.curves.size(); ++i) {
    if (!remove[i]) kept.push_back(std::move(image.curves[i]));
  }
  const int removed = static_cast<int>(image.curves.size() - kept.size());
  image.curves = std::move(kept);
  return removed;
}

}  // namespace vicc_glyphs::design
