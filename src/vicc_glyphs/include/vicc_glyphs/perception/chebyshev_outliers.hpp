#pragma once
// Two-step Chebyshev outlier detection (Amidan, Ferryman and Cooley 2005), as the thesis
// applies it to the survey answers (6.1.3.3, p1 = 0.375, p2 = 0.175).
//
// Step 1 removes potential outliers outside mean +- k1 sd with k1 = 1/sqrt(p1) (Chebyshev:
// P(|X - mu| >= k sd) <= 1/k^2); step 2 recomputes mean and sd from the remaining values and
// flags every original value outside mean +- k2 sd, k2 = 1/sqrt(p2), as an outlier. If the
// values left after step 1 are all equal (sd 0, frequent with integer answers), step 2 would
// flag every other value; the step-1 limits are used instead.

#include <vector>

namespace vicc_glyphs::perception {

struct ChebyshevParameters {
  double p1 = 0.375;
  double p2 = 0.175;
};

/// The limits values must lie within to be kept (infinite for fewer than three values).
struct OutlierLimits {
  double lower = -1e300;
  double upper = 1e300;
};
OutlierLimits chebyshevLimits(const std::vector<double>& values,
                              const ChebyshevParameters& parameters = {});

/// Per value: true if it is an outlier (outside chebyshevLimits). Fewer than three values: none.
/// Throws std::invalid_argument unless both p are in (0, 1].
std::vector<bool> chebyshevOutliers(const std::vector<double>& values,
                                    const ChebyshevParameters& parameters = {});

}  // namespace vicc_glyphs::perception
