#include "vicc_glyphs/bspline/chain_parameter_map.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vicc_glyphs {
namespace bspline {

ChainParameterMap::ChainParameterMap(std::vector<double> breakpoints)
    : breakpoints_(std::move(breakpoints)) {
  if (breakpoints_.size() < 2) {
    throw std::invalid_argument("ChainParameterMap: need at least 2 breakpoints");
  }
  for (std::size_t i = 0; i < breakpoints_.size(); ++i) {
    if (!std::isfinite(breakpoints_[i])) {
      throw std::invalid_argument("ChainParameterMap: breakpoint is not finite");
    }
    if (i > 0 && !(breakpoints_[i] > breakpoints_[i - 1])) {
      throw std::invalid_argument("ChainParameterMap: breakpoints must increase strictly");
    }
  }
}

double ChainParameterMap::toSplineParameter(double s) const {
  if (!std::isfinite(s)) throw std::invalid_argument("ChainParameterMap: s is not finite");
  const int segments = segmentCount();
  const double clamped = std::clamp(s, 0.0, static_cast<double>(segments));
  const int k = std::min(static_cast<int>(std::floor(clamped)), segments - 1);
  const double local = clamped - k;
  return (1.0 - local) * breakpoints_[k] + local * breakpoints_[k + 1];
}

double ChainParameterMap::toCurveParameter(double u) const {
  if (!std::isfinite(u)) throw std::invalid_argument("ChainParameterMap: u is not finite");
  const double clamped = std::clamp(u, breakpoints_.front(), breakpoints_.back());
  const auto upper = std::upper_bound(breakpoints_.begin(), breakpoints_.end(), clamped);
  const int k = std::min(static_cast<int>(upper - breakpoints_.begin()) - 1, segmentCount() - 1);
  const double local = (clamped - breakpoints_[k]) / (breakpoints_[k + 1] - breakpoints_[k]);
  return std::min(k + local, static_cast<double>(segmentCount()));
}

}  // namespace bspline
}  // namespace vicc_glyphs
