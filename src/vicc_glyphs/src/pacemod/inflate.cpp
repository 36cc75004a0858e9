#include "vicc_glyphs/pacemod/inflate.hpp"

#include <cmath>
#include <stdexcept>

#include "vicc_glyphs/pacemod/offset_contour.hpp"
#include "vicc_glyphs/pacemod/polyline.hpp"
#include "vicc_glyphs/pacemod/wave_spec.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

std::vector<ColorPoint> uniformSide(const std::vector<ColorPoint>& points, double end) {
  if (points.empty()) return {};
  Color sum = Color::Zero();
  for (const ColorPoint& p : points) sum += p.rgb;
  const Color mean = sum / points.size();
  return {{0.0, mean}, {end, mean}};
}

std::vector<BlurPoint> uniformBlur(const std::vector<BlurPoint>& points, double end) {
  if (points.empty()) return {};
  double sum = 0.0;
  for (const BlurPoint& p : points) sum += p.sigma;
  return {{0.0, sum / points.size()}, {end, sum / points.size()}};
}

}  // namespace

std::vector<CurveInflateReport> inflateCurves(DiffusionCurveImage& image,
                                              const std::vector<int>& curves, double offset_mm,
                                              double glyph_size_mm) {
  if (!std::isfinite(offset_mm)) throw std::invalid_argument("inflate offset must be finite");
  if (!std::isfinite(glyph_size_mm) || !(glyph_size_mm > 0.0) || image.width < 1) {
    throw std::invalid_argument("glyph_size_mm must be a finite number > 0");
  }
  const std::string too_large = checkDisplacement("inflate offset", offset_mm, glyph_size_mm);
  if (!too_large.empty()) throw std::invalid_argument(too_large);
  const double px_per_mm = image.width / glyph_size_mm;
  std::vector<CurveInflateReport> reports;
  for (int index : curves) {
    if (index < 0 || index >= static_cast<int>(image.curves.size())) {
      throw std::invalid_argument("curve index " + std::to_string(index) + " out of range");
    }
    DiffusionCurve& curve = image.curves[index];
    CurveInflateReport report;
    report.curve = index;
    report.offset_mm = offset_mm;
    const Polyline line = sampleCurve(curve, 16);
    report.area_before_mm2 = std::abs(polylineArea(line)) / (px_per_mm * px_per_mm);
    if (line.size() < 5 || (line.front() - line.back()).norm() > 1e-6) {
      report.skipped = "not a closed curve";
    } else {
      const Polyline isoline = offsetIsoline(line, offset_mm * px_per_mm);
      if (isoline.size() < 5) {
        report.skipped = "nothing is left of the region at this offset";
      } else {
        curve.control_points = closedBezierFit(isoline);
        const double end = curve.segmentCount();
        curve.left_colors = uniformSide(curve.left_colors, end);
        curve.right_colors = uniformSide(curve.right_colors, end);
        curve.blur_points = uniformBlur(curve.blur_points, end);
        report.area_after_mm2 =
            std::abs(polylineArea(sampleCurve(curve, 16))) / (px_per_mm * px_per_mm);
      }
    }
    if (!report.skipped.empty()) report.area_after_mm2 = report.area_before_mm2;
    reports.push_back(report);
  }
  return reports;
}

}  // namespace pacemod
}  // namespace vicc_glyphs
