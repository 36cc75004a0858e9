#include "vicc_glyphs/perception/chebyshev_outliers.hpp"

#include <cmath>
#include <stdexcept>

namespace vicc_glyphs::perception {
namespace {

struct MeanAndDeviation {
  double mean = 0.0;
  double deviation = 0.0;  ///< sample standard deviation
};

MeanAndDeviation meanAndDeviation(const std::vector<double>& values, const std::vector<bool>& use) {
  double sum = 0.0;
  int count = 0;
  for (size_t i = 0; i < values.size(); ++i) {
    if (use[i]) sum += values[i], ++count;
  }
  MeanAndDeviation result;
  if (count == 0) return result;
  result.mean = sum / count;
  double squares = 0.0;
  for (size_t i = 0; i < values.size(); ++i) {
    if (use[i]) squares += (values[i] - result.mean) * (values[i] - result.mean);
  }
  result.deviation = count > 1 ? std::sqrt(squares / (count - 1)) : 0.0;
  return result;
}

}  // namespace

OutlierLimits chebyshevLimits(const std::vector<double>& values,
                              const ChebyshevParameters& parameters) {
  for (double p : {parameters.p1, parameters.p2}) {
    if (!(p > 0.0) || !(p <= 1.0)) {
      throw std::invalid_argument("Chebyshev outlier probabilities must be in (0, 1]");
    }
  }
  if (values.size() < 3) return {};
  const std::vector<bool> all(values.size(), true);
  const MeanAndDeviation first = meanAndDeviation(values, all);
  const double k1 = 1.0 / std::sqrt(parameters.p1);
  std::vector<bool> kept(values.size());
  for (size_t i = 0; i < values.size(); ++i) {
    kept[i] = std::abs(values[i] - first.mean) <= k1 * first.deviation;
  }
  MeanAndDeviation second = meanAndDeviation(values, kept);
  double limit = second.deviation / std::sqrt(parameters.p2);
  if (second.deviation == 0.0) {
    second = first;
    limit = k1 * first.deviation;
  }
  return {second.mean - limit, second.mean + limit};
}

std::vector<bool> chebyshevOutliers(const std::vector<double>& values,
                                    const ChebyshevParameters& parameters) {
  const OutlierLimits limits = chebyshevLimits(values, parameters);
  std::vector<bool> outlier(values.size());
  for (size_t i = 0; i < values.size(); ++i) {
    outlier[i] = values[i] < limits.lower || values[i] > limits.upper;
  }
  return outlier;
}

}  // namespace vicc_glyphs::perception
