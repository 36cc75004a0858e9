#include "vicc_glyphs/bspline/arc_length.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vicc_glyphs {
namespace bspline {
namespace {

// Linear interpolation in a table of increasing `from` values; `x` is clamped to its range.
double interpolate(const std::vector<double>& from, const std::vector<double>& to, double x) {
  if (x <= from.front()) return to.front();
  if (x >= from.back()) return to.back();
  const auto upper = std::upper_bound(from.begin(), from.end(), x);
  const std::size_t i = static_cast<std::size_t>(upper - from.begin());
  const double span = from[i] - from[i - 1];
  const double w = span > 0.0 ? (x - from[i - 1]) / span : 0.0;
  return (1.0 - w) * to[i - 1] + w * to[i];
}

}  // namespace

ArcLengthTable::ArcLengthTable(const BSplineCurve& curve, int samples_per_span) {
  if (samples_per_span < 1) {
    throw std::invalid_argument("ArcLengthTable: need at least 1 sample per knot span");
  }
  const std::vector<double> breaks = curve.breakpoints();
  parameters_.push_back(breaks.front());
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
    for (int i = 1; i <= samples_per_span; ++i) {
      const double w = static_cast<double>(i) / samples_per_span;
      parameters_.push_back(i == samples_per_span ? breaks[k + 1]
                                                  : (1.0 - w) * breaks[k] + w * breaks[k + 1]);
    }
  }
  lengths_.assign(parameters_.size(), 0.0);
  Point2 previous = curve.pointAt(parameters_.front());
  for (std::size_t i = 1; i < parameters_.size(); ++i) {
    const Point2 current = curve.pointAt(parameters_[i]);
    lengths_[i] = lengths_[i - 1] + (current - previous).norm();
    previous = current;
  }
}

double ArcLengthTable::lengthAt(double u) const {
  if (!std::isfinite(u)) throw std::invalid_argument("ArcLengthTable: u is not finite");
  return interpolate(parameters_, lengths_, u);
}

double ArcLengthTable::parameterAt(double length) const {
  if (!std::isfinite(length)) throw std::invalid_argument("ArcLengthTable: length not finite");
  return interpolate(lengths_, parameters_, length);
}

std::vector<double> ArcLengthTable::equidistantParameters(int count) const {
  if (count < 2) throw std::invalid_argument("ArcLengthTable: need at least 2 parameters");
  std::vector<double> result(count);
  for (int i = 0; i < count; ++i) {
    result[i] = parameterAt(totalLength() * i / (count - 1));
  }
  result.back() = parameters_.back();
  return result;
}

}  // namespace bspline
}  // namespace vicc_glyphs
