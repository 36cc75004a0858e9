#include "vicc_glyphs/perception/level_distribution.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vicc_glyphs::perception {
namespace {

constexpr double kPi = 3.14159265358979323846;

double normalPdf(double x, const GaussianComponent& g) {
  const double z = (x - g.mean) / g.sigma;
  return std::exp(-0.5 * z * z) / (g.sigma * std::sqrt(2.0 * kPi));
}

double logLikelihood(const std::vector<double>& values,
                     const std::vector<GaussianComponent>& components) {
  double sum = 0.0;
  for (double x : values) {
    double density = 0.0;
    for (const GaussianComponent& g : components) density += g.weight * normalPdf(x, g);
    sum += std::log(std::max(density, 1e-300));
  }
  return sum;
}

LevelDistribution finish(const std::vector<double>& values,
                         std::vector<GaussianComponent> components) {
  LevelDistribution result;
  result.components = std::move(components);
  result.log_likelihood = logLikelihood(values, result.components);
  const double parameters = result.isMixture() ? 5.0 : 2.0;
  result.bic =
      parameters * std::log(static_cast<double>(values.size())) - 2.0 * result.log_likelihood;
  return result;
}

double sampleQuantile(std::vector<double> sorted, double p) {
  std::sort(sorted.begin(), sorted.end());
  const double at = p * (sorted.size() - 1);
  const size_t below = static_cast<size_t>(std::floor(at));
  const size_t above = std::min(below + 1, sorted.size() - 1);
  return sorted[below] + (at - below) * (sorted[above] - sorted[below]);
}

// One EM step: responsibilities, then weights, means and sigmas (floored).
void emStep(const std::vector<double>& values, std::vector<GaussianComponent>& g,
            double min_sigma) {
  double weight[2] = {0, 0}, sum[2] = {0, 0}, squares[2] = {0, 0};
  for (double x : values) {
    const double d0 = g[0].weight * normalPdf(x, g[0]);
    const double d1 = g[1].weight * normalPdf(x, g[1]);
    const double total = d0 + d1;
    const double r0 = total > 0.0 ? d0 / total : 0.5;
    weight[0] += r0, weight[1] += 1.0 - r0;
    sum[0] += r0 * x, sum[1] += (1.0 - r0) * x;
  }
  for (int k = 0; k < 2; ++k) {
    if (weight[k] > 0.0) g[k].mean = sum[k] / weight[k];
  }
  for (double x : values) {
    const double d0 = g[0].weight * normalPdf(x, g[0]);
    const double d1 = g[1].weight * normalPdf(x, g[1]);
    const double total = d0 + d1;
    const double r0 = total > 0.0 ? d0 / total : 0.5;
    squares[0] += r0 * (x - g[0].mean) * (x - g[0].mean);
    squares[1] += (1.0 - r0) * (x - g[1].mean) * (x - g[1].mean);
  }
  for (int k = 0; k < 2; ++k) {
    g[k].weight = weight[k] / values.size();
    g[k].sigma = std::max(min_sigma, weight[k] > 0.0 ? std::sqrt(squares[k] / weight[k]) : 0.0);
  }
}

// A mixture is bimodal if its density dips between the two means (a unimodal mixture rises
// monotonically from one mean to the other or has its only peak between them).
bool hasTwoModes(const LevelDistribution& d) {
  const GaussianComponent& low = d.components[0];
  const GaussianComponent& high = d.components[1];
  const auto density = [&](double x) {
    return low.weight * normalPdf(x, low) + high.weight * normalPdf(x, high);
  };
  const double smaller_end = std::min(density(low.mean), density(high.mean));
  constexpr int kSteps = 200;
  for (int i = 1; i < kSteps; ++i) {
    const double x = low.mean + (high.mean - low.mean) * i / kSteps;
    if (density(x) < 0.999 * smaller_end) return true;
  }
  return false;
}

double normalCdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }
double standardPdf(double z) { return std::exp(-0.5 * z * z) / std::sqrt(2.0 * kPi); }

// Fixed point for the untruncated mean and sd whose normal, truncated to [lower, upper], has
// the sample mean and variance (standard truncated-normal moments).
std::pair<double, double> untruncatedMoments(double mean, double variance,
                                             const Truncation& truncation) {
  double mu = mean, sigma = std::sqrt(variance);
  for (int i = 0; i < 200 && sigma > 0.0; ++i) {
    const double alpha = std::max(-40.0, (truncation.lower - mu) / sigma);
    const double beta = std::min(40.0, (truncation.upper - mu) / sigma);
    const double mass = normalCdf(beta) - normalCdf(alpha);
    if (!(mass > 1e-9)) break;
    const double shift = (standardPdf(alpha) - standardPdf(beta)) / mass;
    const double shrink =
        1.0 + (alpha * standardPdf(alpha) - beta * standardPdf(beta)) / mass - shift * shift;
    if (!(shrink > 1e-6)) break;
    const double next_sigma = std::sqrt(variance / shrink);
    const double next_mu = mean - next_sigma * shift;
    const bool settled = std::abs(next_sigma - sigma) < 1e-12 && std::abs(next_mu - mu) < 1e-12;
    mu = next_mu, sigma = next_sigma;
    if (settled) break;
  }
  return {mu, sigma};
}

}  // namespace

double LevelDistribution::mean() const {
  double sum = 0.0;
  for (const GaussianComponent& g : components) sum += g.weight * g.mean;
  return sum;
}

double LevelDistribution::cdf(double x) const {
  double sum = 0.0;
  for (const GaussianComponent& g : components) {
    sum += g.weight * 0.5 * std::erfc(-(x - g.mean) / (g.sigma * std::sqrt(2.0)));
  }
  return sum;
}

double LevelDistribution::quantile(double p) const {
  double low = components.front().mean, high = low;
  for (const GaussianComponent& g : components) {
    low = std::min(low, g.mean - 10.0 * g.sigma);
    high = std::max(high, g.mean + 10.0 * g.sigma);
  }
  for (int i = 0; i < 100; ++i) {
    const double middle = 0.5 * (low + high);
    (cdf(middle) < p ? low : high) = middle;
  }
  return 0.5 * (low + high);
}

double LevelDistribution::interval50() const { return quantile(0.75) - quantile(0.25); }

LevelDistribution fitGaussian(const std::vector<double>& values, const DistributionOptions& options,
                              const Truncation& truncation) {
  if (values.size() < 2) throw std::invalid_argument("a Gaussian fit needs at least 2 values");
  double mean = 0.0;
  for (double x : values) mean += x;
  mean /= values.size();
  double squares = 0.0;
  for (double x : values) squares += (x - mean) * (x - mean);
  const auto [mu, sigma] = untruncatedMoments(mean, squares / values.size(), truncation);
  return finish(values, {{1.0, mu, std::max(options.min_sigma, sigma)}});
}

LevelDistribution fitGaussianMixture(const std::vector<double>& values,
                                     const DistributionOptions& options) {
  if (values.size() < 5) throw std::invalid_argument("a mixture fit needs at least 5 values");
  const LevelDistribution single = fitGaussian(values, options);
  const double sigma = std::max(options.min_sigma, 0.5 * single.components[0].sigma);
  std::vector<GaussianComponent> g{{0.5, sampleQuantile(values, 0.25), sigma},
                                   {0.5, sampleQuantile(values, 0.75), sigma}};
  for (int i = 0; i < options.em_iterations; ++i) emStep(values, g, options.min_sigma);
  if (g[0].mean > g[1].mean) std::swap(g[0], g[1]);
  return finish(values, g);
}

LevelDistribution fitLevelDistribution(const std::vector<double>& values,
                                       const DistributionOptions& options,
                                       const Truncation& truncation) {
  LevelDistribution single = fitGaussian(values, options, truncation);
  if (values.size() < 5) return single;
  LevelDistribution mixture = fitGaussianMixture(values, options);
  return mixture.bic < single.bic && hasTwoModes(mixture) ? mixture : single;
}

}  // namespace vicc_glyphs::perception
