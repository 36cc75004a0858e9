#include "vicc_glyphs/pacemod/dashes.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "vicc_glyphs/pacemod/offset_contour.hpp"
#include "vicc_glyphs/pacemod/polyline.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

constexpr int kMaxDashes = 10000;

// Colour points of the dashed side: interval i (of 2N) is the dash colour when i is odd.
std::vector<ColorPoint> dashedColors(const std::vector<ColorPoint>& original,
                                     const ChainArcLength& table, int dashes, double transition,
                                     const Color& dash) {
  const double length = table.totalLength();
  const int intervals = 2 * dashes;
  const double interval = length / intervals;
  const double offset = std::min(transition, 0.25 * interval);
  auto colorAt = [&](double l, int i) {
    return i % 2 ? dash : interpolateColor(original, table.parameterAt(l));
  };
  std::vector<ColorPoint> result{{table.parameterAt(0.0), colorAt(0.0, 0)}};
  for (int m = 1; m < intervals; ++m) {
    const double boundary = m * interval;
    result.push_back({table.parameterAt(boundary - offset), colorAt(boundary - offset, m - 1)});
    result.push_back({table.parameterAt(boundary + offset), colorAt(boundary + offset, m)});
  }
  result.push_back({table.parameterAt(length), colorAt(length, intervals - 1)});
  return result;
}

// The barrier: same orientation as the contour, emitting the original inner colour towards
// the inside only.
DiffusionCurve barrierCurve(const Polyline& isoline, bool inside_is_right, const Color& inner) {
  DiffusionCurve barrier;
  barrier.control_points = closedBezierFit(isoline);
  const double end = barrier.segmentCount();
  std::vector<ColorPoint> colors{{0.0, inner}, {end, inner}};
  (inside_is_right ? barrier.right_colors : barrier.left_colors) = colors;
  barrier.left_emits = !inside_is_right;
  barrier.right_emits = inside_is_right;
  return barrier;
}

}  // namespace

ChainArcLength::ChainArcLength(const DiffusionCurve& curve, int samples_per_segment) {
  const int segments = std::max(curve.segmentCount(), 1);
  const int count = segments * std::max(samples_per_segment, 1);
  Point2 last = curve.pointAt(0.0);
  parameters_.push_back(0.0);
  lengths_.push_back(0.0);
  for (int i = 1; i <= count; ++i) {
    const double s = static_cast<double>(i) * segments / count;
    const Point2 p = curve.pointAt(s);
    parameters_.push_back(s);
    lengths_.push_back(lengths_.back() + (p - last).norm());
    last = p;
  }
}

double ChainArcLength::parameterAt(double length) const {
  length = std::clamp(length, 0.0, lengths_.back());
  const auto upper = std::upper_bound(lengths_.begin(), lengths_.end(), length);
  if (upper == lengths_.end()) return parameters_.back();
  const std::size_t i = upper - lengths_.begin();
  const double span = lengths_[i] - lengths_[i - 1];
  const double t = span > 0.0 ? (length - lengths_[i - 1]) / span : 0.0;
  return parameters_[i - 1] + t * (parameters_[i] - parameters_[i - 1]);
}

std::string validate(const DashSpec& spec) {
  if (spec.count < 1 || spec.count > kMaxDashes) return "count must be from 1 to 10000";
  if (!spec.color.allFinite() || spec.color.minCoeff() < 0.0 || spec.color.maxCoeff() > 1.0) {
    return "color must be RGB in [0, 1]";
  }
  if (!std::isfinite(spec.transition_mm) || !(spec.transition_mm > 0.0)) {
    return "transition_mm must be a finite number > 0";
  }
  if (!std::isfinite(spec.barrier_offset_mm) || spec.barrier_offset_mm < 0.0) {
    return "barrier_offset_mm must be a finite number >= 0";
  }
  return "";
}

std::vector<CurveDashReport> applyDashes(DiffusionCurveImage& image, const std::vector<int>& curves,
                                         const DashSpec& spec, double glyph_size_mm) {
  const std::string problem = validate(spec);
  if (!problem.empty()) throw std::invalid_argument(problem);
  if (!std::isfinite(glyph_size_mm) || !(glyph_size_mm > 0.0) || image.width < 1) {
    throw std::invalid_argument("glyph_size_mm must be a finite number > 0");
  }
  const double px_per_mm = image.width / glyph_size_mm;
  const int original_count = static_cast<int>(image.curves.size());
  std::vector<CurveDashReport> reports;
  for (int index : curves) {
    if (index < 0 || index >= original_count) {
      throw std::invalid_argument("curve index " + std::to_string(index) + " out of range");
    }
    CurveDashReport report;
    report.curve = index;
    DiffusionCurve& curve = image.curves[index];
    const Polyline line = sampleCurve(curve, 16);
    if (line.size() < 5 || (line.front() - line.back()).norm() > 1e-6) {
      report.skipped = "not a closed curve";
      reports.push_back(report);
      continue;
    }
    const bool inside_is_right = polylineArea(line) > 0.0;
    std::vector<ColorPoint>& inner = inside_is_right ? curve.right_colors : curve.left_colors;
    // The barrier repeats the colour that covered most of the inner side. A mean would mix in
    // a neighbour's colour that the side recorded along a shared stretch (as inflation did).
    const std::optional<Color> inner_color = dominantColor(inner);
    if (!inner_color || !(inside_is_right ? curve.right_emits : curve.left_emits)) {
      report.skipped = "its inner side emits no colour to dash";
      reports.push_back(report);
      continue;
    }
    const ChainArcLength table(curve);
    const double dash_px = table.totalLength() / (2.0 * spec.count);
    // Shorter than a pixel (or than its two hard transitions) a dash is not drawn: the contour
    // would read as undashed, another level. As for waves, an error instead of such a glyph.
    const double shortest_px = std::max(1.0, 2.0 * spec.transition_mm * px_per_mm);
    if (dash_px < shortest_px) {
      throw std::invalid_argument("dashes: " + std::to_string(spec.count) + " dashes on curve " +
                                  std::to_string(index) + " would be " + std::to_string(dash_px) +
                                  " px long, shorter than " + std::to_string(shortest_px) +
                                  " px (fewer dashes or a larger glyph)");
    }
    report.dashes = spec.count;
    report.dash_length_mm = dash_px / px_per_mm;
    inner = dashedColors(inner, table, spec.count, spec.transition_mm * px_per_mm, spec.color);
    if (spec.barrier_offset_mm > 0.0) {
      const Polyline isoline = offsetIsoline(line, -spec.barrier_offset_mm * px_per_mm);
      if (isoline.size() >= 5) {
        image.curves.push_back(barrierCurve(isoline, inside_is_right, *inner_color));
        report.barrier_curve = static_cast<int>(image.curves.size()) - 1;
      }
    }
    reports.push_back(report);
  }
  return reports;
}

}  // namespace pacemod
}  // namespace vicc_glyphs
