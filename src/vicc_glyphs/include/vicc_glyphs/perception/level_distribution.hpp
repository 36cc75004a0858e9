#pragma once
// Distribution of the perceived magnitudes answered for one stimulus level (thesis 6.1.4.3):
// a Gaussian, or a two-component Gaussian mixture where the answers are bimodal (the mixture
// has the lower Bayesian information criterion and its density dips between the two means:
// a merely flat-topped or skewed level, e.g. after outlier removal cut its tails, stays a
// Gaussian); its 50 % interval is [q25, q75] of the fitted distribution
// (symmetric about the mean for a Gaussian).

#include <vector>

namespace vicc_glyphs::perception {

struct GaussianComponent {
  double weight = 1.0;
  double mean = 0.0;
  double sigma = 1.0;
};

struct LevelDistribution {
  std::vector<GaussianComponent> components;  ///< one or two
  double log_likelihood = 0.0;
  double bic = 0.0;  ///< k ln n - 2 ln L, k = 2 or 5

  double mean() const;
  double cdf(double x) const;
  /// The p-quantile (bisection on the mixture CDF), p in (0, 1).
  double quantile(double p) const;
  /// Width of the central 50 % interval, q75 - q25.
  double interval50() const;
  bool isMixture() const { return components.size() == 2; }
};

struct DistributionOptions {
  /// Lower bound on every sigma: answers are given in whole adu, so a component may not
  /// shrink below the rounding error's deviation, 1/sqrt(12) adu.
  double min_sigma = 0.28867513459481287;
  int em_iterations = 300;
};

/// Values known to come from [lower, upper] only (the outlier limits they passed): a Gaussian
/// fitted to them as if untruncated is too narrow (about 10 % at +-2.1 sd).
struct Truncation {
  double lower = -1e300;
  double upper = 1e300;
};

/// Gaussian by moments, corrected for `truncation` (the mean and sd whose truncated moments
/// match the sample's). Needs at least 2 values (std::invalid_argument).
LevelDistribution fitGaussian(const std::vector<double>& values,
                              const DistributionOptions& options = {},
                              const Truncation& truncation = {});
/// Two-component mixture by EM, started from the lower and upper quartiles. Needs at least 5
/// values (std::invalid_argument).
LevelDistribution fitGaussianMixture(const std::vector<double>& values,
                                     const DistributionOptions& options = {});
/// The Gaussian or, when it has the lower BIC and two modes (and there are >= 5 values), the
/// mixture.
/// The single Gaussian is corrected for `truncation`; the mixture is not (its levels are
/// wide, the outlier limits lie far out in its tails).
LevelDistribution fitLevelDistribution(const std::vector<double>& values,
                                       const DistributionOptions& options = {},
                                       const Truncation& truncation = {});

}  // namespace vicc_glyphs::perception
