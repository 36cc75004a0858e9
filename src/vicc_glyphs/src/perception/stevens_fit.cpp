#include "vicc_glyphs/perception/stevens_fit.hpp"

#include <ceres/ceres.h>

#include <cmath>
#include <set>
#include <stdexcept>

namespace vicc_glyphs::perception {
namespace {

struct PowerResidual {
  double x, y;
  template <typename T>
  bool operator()(const T* a, const T* b, const T* c, T* residual) const {
    residual[0] = a[0] * ceres::pow(T(x), b[0]) + c[0] - T(y);
    return true;
  }
};

// Slope and intercept of the least-squares line, the start for b = 1.
std::pair<double, double> linearRegression(const std::vector<double>& x,
                                           const std::vector<double>& y) {
  double mx = 0, my = 0;
  for (size_t i = 0; i < x.size(); ++i) mx += x[i], my += y[i];
  mx /= x.size(), my /= y.size();
  double sxy = 0, sxx = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
  }
  const double slope = sxy / sxx;
  return {slope, my - slope * mx};
}

}  // namespace

StevensFit fitStevensPowerFunction(const std::vector<double>& stimuli,
                                   const std::vector<double>& perceived) {
  if (stimuli.size() != perceived.size()) {
    throw std::invalid_argument("stimuli and perceived values differ in number");
  }
  std::set<double> distinct;
  for (double x : stimuli) {
    if (!(x > 0.0) || !std::isfinite(x)) {
      throw std::invalid_argument("stimuli must be positive (adu scales start at 1)");
    }
    distinct.insert(x);
  }
  if (distinct.size() < 3) throw std::invalid_argument("fitting a, b, c needs 3 distinct stimuli");
  const auto [slope, intercept] = linearRegression(stimuli, perceived);
  double a = slope > 0.0 ? slope : 1.0, b = 1.0, c = slope > 0.0 ? intercept : 0.0;

  ceres::Problem problem;
  for (size_t i = 0; i < stimuli.size(); ++i) {
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<PowerResidual, 1, 1, 1, 1>(
                                 new PowerResidual{stimuli[i], perceived[i]}),
                             nullptr, &a, &b, &c);
  }
  problem.SetParameterLowerBound(&a, 0, 1e-9);
  problem.SetParameterLowerBound(&b, 0, 0.05);
  problem.SetParameterUpperBound(&b, 0, 10.0);
  ceres::Solver::Options options;
  options.max_num_iterations = 200;
  options.function_tolerance = 1e-12;
  options.parameter_tolerance = 1e-12;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);

  StevensFit fit;
  fit.function = {a, b, c};
  fit.converged = summary.termination_type == ceres::CONVERGENCE;
  fit.rms_residual = std::sqrt(2.0 * summary.final_cost / stimuli.size());
  return fit;
}

}  // namespace vicc_glyphs::perception
