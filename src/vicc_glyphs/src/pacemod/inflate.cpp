#include "vicc_glyphs/pacemod/inflate.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>

#include "vicc_glyphs/pacemod/offset_contour.hpp"
#include "vicc_glyphs/pacemod/polygon_crossings.hpp"
#include "vicc_glyphs/pacemod/polyline.hpp"
#include "vicc_glyphs/pacemod/wave_spec.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

// One colour for a side of a re-fitted contour: the one that covered most of it. Where the
// side recorded a neighbour's colour along a shared stretch (a rain drop touching the cloud),
// a mean of the points (4 of the cloud's grey, 2 of white) made the whole outside of the
// inflated drops grey, and the sky below them a grey haze.
std::vector<ColorPoint> uniformSide(const std::vector<ColorPoint>& points, double end) {
  const std::optional<Color> dominant = dominantColor(points);
  if (!dominant) return {};
  return {{0.0, *dominant}, {end, *dominant}};
}

std::vector<BlurPoint> uniformBlur(const std::vector<BlurPoint>& points, double end) {
  if (points.empty()) return {};
  double sum = 0.0;
  for (const BlurPoint& p : points) sum += p.sigma;
  return {{0.0, sum / points.size()}, {end, sum / points.size()}};
}

// Gap an inflated part keeps to a neighbouring contour (image pixels), doubled while the fit of
// its isoline still crosses the neighbour, at most kClearanceTries times.
constexpr double kClearancePx = 1.0;
constexpr int kClearanceTries = 3;

// Whether more than half of the points of `a` lie inside the closed polyline `b`.
bool mostlyInside(const Polyline& a, const Polyline& b) {
  std::size_t inside = 0;
  for (const Point2& p : a) inside += insidePolygon(p, b) ? 1 : 0;
  return 2 * inside > a.size();
}

struct Box {
  Point2 low, high;
};

Box boxOf(const Polyline& line) {
  Box box{line.front(), line.front()};
  for (const Point2& p : line) {
    box.low = box.low.cwiseMin(p);
    box.high = box.high.cwiseMax(p);
  }
  return box;
}

// The closed contours within `reach` pixels of contour `index` that it must stay clear of when
// inflated: those that neither enclose it nor lie inside it (a part beside it, e.g. the cloud a
// rain drop hangs from). Where the inflated region reached into one of them, the region's side
// colour (the dominant one that inflating gives each side) would be wrong there: a white halo in a
// grey cloud.
std::vector<Polyline> neighbours(const std::vector<Polyline>& lines, int index, double reach) {
  const Box own = boxOf(lines[index]);
  std::vector<Polyline> found;
  for (int j = 0; j < static_cast<int>(lines.size()); ++j) {
    if (j == index || !isClosedPolyline(lines[j])) continue;
    const Box other = boxOf(lines[j]);
    if ((other.low - own.high).maxCoeff() > reach || (own.low - other.high).maxCoeff() > reach) {
      continue;  // too far away to be reached
    }
    if (mostlyInside(lines[index], lines[j]) || mostlyInside(lines[j], lines[index])) continue;
    found.push_back(lines[j]);
  }
  return found;
}

// Whether the closed Bezier chain crosses one of `others`.
bool crossesAny(const std::vector<Point2>& chain, const std::vector<Polyline>& others) {
  DiffusionCurve curve;
  curve.control_points = chain;
  std::vector<Polyline> lines{sampleCurve(curve, 16)};
  lines.insert(lines.end(), others.begin(), others.end());
  for (const Crossing& crossing : findCrossings(lines)) {
    if (crossing.a.line == 0 && crossing.b.line != 0) return true;
  }
  return false;
}

constexpr const char* kNothingLeft = "nothing is left of the region at this offset";

// The inflated (or shrunk) contour as a closed Bezier chain; empty, with the reason in
// report.skipped, when there is none; report.limited when it stopped short of a neighbour.
std::vector<Point2> offsetChain(const Polyline& line, double offset_px,
                                const std::vector<Polyline>& others, CurveInflateReport& report) {
  if (offset_px <= 0.0 || others.empty()) {
    const Polyline isoline = offsetIsoline(line, offset_px);
    if (isoline.size() < 5) report.skipped = kNothingLeft;
    return isoline.size() < 5 ? std::vector<Point2>{} : closedBezierFit(isoline);
  }
  double clearance = kClearancePx;
  for (int attempt = 0; attempt < kClearanceTries; ++attempt, clearance *= 2.0) {
    bool limited = false;
    const Polyline isoline = offsetIsolineAvoiding(line, offset_px, others, clearance, &limited);
    if (isoline.size() < 5) {
      report.skipped = kNothingLeft;
      return {};
    }
    std::vector<Point2> chain = closedBezierFit(isoline);
    if (!crossesAny(chain, others)) {
      report.limited = limited;
      return chain;
    }
  }
  report.skipped = "inflating it would cross a neighbouring contour";
  return {};
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
  std::vector<Polyline> lines;  // of the image as it was: the neighbours' places
  for (const DiffusionCurve& curve : image.curves) lines.push_back(sampleCurve(curve, 16));
  std::vector<CurveInflateReport> reports;
  for (int index : curves) {
    if (index < 0 || index >= static_cast<int>(image.curves.size())) {
      throw std::invalid_argument("curve index " + std::to_string(index) + " out of range");
    }
    DiffusionCurve& curve = image.curves[index];
    CurveInflateReport report;
    report.curve = index;
    report.offset_mm = offset_mm;
    const Polyline& line = lines[index];
    report.area_before_mm2 = std::abs(polylineArea(line)) / (px_per_mm * px_per_mm);
    if (!isClosedPolyline(line)) {
      report.skipped = "not a closed curve";
    } else if (offset_mm == 0.0) {
      // The curve as it is: a re-fit of its isoline would move it by up to a few tenths of a
      // pixel and average its side colours.
      report.area_after_mm2 = report.area_before_mm2;
    } else {
      const double offset_px = offset_mm * px_per_mm;
      const double reach = offset_px + kClearancePx * (1 << kClearanceTries);
      const std::vector<Polyline> others =
          offset_px > 0.0 ? neighbours(lines, index, reach) : std::vector<Polyline>{};
      const std::vector<Point2> chain = offsetChain(line, offset_px, others, report);
      if (!chain.empty()) {
        curve.control_points = chain;
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
