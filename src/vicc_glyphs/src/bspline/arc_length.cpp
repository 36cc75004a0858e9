#include "vicc_glyphs/bspline/arc_length.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace vicc_glyphs {
namespace bspline {
namespace {

// Linear interpolation between entries i - 1 and i of a table, from[i - 1] <= x < from[i].
double interpolateAt(std::size_t i, const std::vector<double>& from, const std::vector<double>& to,
                     double x) {
  const double span = from[i] - from[i - 1];
  const double w = span > 0.0 ? (x - from[i - 1]) / span : 0.0;
  return (1.0 - w) * to[i - 1] + w * to[i];
}

// Linear interpolation in a table of increasing `from` values; `x` is clamped to its range.
double interpolate(const std::vector<double>& from, const std::vector<double>& to, double x) {
  if (x <= from.front()) return to.front();
  if (x >= from.back()) return to.back();
  const auto upper = std::upper_bound(from.begin(), from.end(), x);
  return interpolateAt(static_cast<std::size_t>(upper - from.begin()), from, to, x);
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

std::vector<double> ArcLengthTable::parametersAt(const std::vector<double>& lengths) const {
  std::vector<double> result;
  result.reserve(lengths.size());
  std::size_t upper = 0;  // the first table entry above the current length, as in interpolate
  double previous = -std::numeric_limits<double>::infinity();
  for (const double length : lengths) {
    if (!std::isfinite(length)) throw std::invalid_argument("ArcLengthTable: length not finite");
    if (length < previous) {
      throw std::invalid_argument(
          "ArcLengthTable: parametersAt needs lengths that do not decrease");
    }
    previous = length;
    if (length <= lengths_.front() || length >= lengths_.back()) {
      result.push_back(length <= lengths_.front() ? parameters_.front() : parameters_.back());
      continue;
    }
    if (upper == 0) {  // the first one is searched, the others walked to
      upper = static_cast<std::size_t>(std::upper_bound(lengths_.begin(), lengths_.end(), length) -
                                       lengths_.begin());
    }
    while (lengths_[upper] <= length) ++upper;
    result.push_back(interpolateAt(upper, lengths_, parameters_, length));
  }
  return result;
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
