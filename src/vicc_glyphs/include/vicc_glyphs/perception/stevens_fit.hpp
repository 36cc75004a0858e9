#pragma once
// Non-linear least-squares fit of e(x) = a x^b + c to (stimulus, perceived) pairs (thesis
// 6.1.3.3) with Ceres (Levenberg-Marquardt, automatic derivatives).

#include <vector>

#include "vicc_glyphs/perception/stevens_power_function.hpp"

namespace vicc_glyphs::perception {

struct StevensFit {
  StevensPowerFunction function;
  double rms_residual = 0.0;  ///< adu
  bool converged = false;
};

/// Fits a, b, c (a > 0, b in [0.05, 10]), started from b = 1 and the linear regression.
/// Needs at least 3 distinct positive stimuli (std::invalid_argument otherwise).
StevensFit fitStevensPowerFunction(const std::vector<double>& stimuli,
                                   const std::vector<double>& perceived);

}  // namespace vicc_glyphs::perception
