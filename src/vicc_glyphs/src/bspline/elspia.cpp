#include "vicc_glyphs/bspline/elspia.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "vicc_glyphs/bspline/curve_energy.hpp"
#include "vicc_glyphs/bspline/fitting.hpp"

namespace vicc_glyphs {
namespace bspline {
namespace {

Eigen::MatrixX2d toMatrix(const std::vector<Point2>& points) {
  Eigen::MatrixX2d m(points.size(), 2);
  for (std::size_t i = 0; i < points.size(); ++i) m.row(i) = points[i].transpose();
  return m;
}

std::vector<Point2> toPoints(const Eigen::MatrixX2d& m) {
  std::vector<Point2> points(m.rows());
  for (int i = 0; i < m.rows(); ++i) points[i] = m.row(i).transpose();
  return points;
}

// 2 / (lambda_min + lambda_max) of the loss Hessian restricted to the moving de Boor points;
// falls back to 1 / lambda_max when the data leave a direction undetermined (lambda_min = 0).
double optimalStep(const Eigen::SparseMatrix<double>& hessian, int first, int count) {
  const Eigen::MatrixXd block = Eigen::MatrixXd(hessian).block(first, first, count, count);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(block, Eigen::EigenvaluesOnly);
  const double lambda_min = std::max(solver.eigenvalues().minCoeff(), 0.0);
  const double lambda_max = solver.eigenvalues().maxCoeff();
  if (!(lambda_max > 0.0)) throw std::invalid_argument("elspiaFit: no data act on the curve");
  return lambda_min > 1e-12 * lambda_max ? 2.0 / (lambda_min + lambda_max) : 1.0 / lambda_max;
}

}  // namespace

ElspiaResult elspiaFit(const BSplineCurve& initial, const std::vector<Point2>& points,
                       const std::vector<double>& parameters, const ElspiaOptions& options) {
  if (points.empty() || points.size() != parameters.size()) {
    throw std::invalid_argument("elspiaFit: need as many parameters as points, at least 1");
  }
  for (const Point2& p : points) {
    if (!p.allFinite()) throw std::invalid_argument("elspiaFit: point not finite");
  }
  if (!(options.energy_weight >= 0.0) || !std::isfinite(options.energy_weight)) {
    throw std::invalid_argument("elspiaFit: energy weight must be finite and >= 0");
  }
  if (options.max_iterations < 1) throw std::invalid_argument("elspiaFit: need >= 1 iteration");
  if (!(options.step >= 0.0) || !std::isfinite(options.step)) {
    throw std::invalid_argument("elspiaFit: step must be finite and >= 0 (0 = automatic)");
  }

  const Eigen::SparseMatrix<double> n = collocationMatrix(initial, parameters);
  const Eigen::SparseMatrix<double> nt = n.transpose();
  const Eigen::SparseMatrix<double> energy = energyMatrix(initial, 1);
  const Eigen::SparseMatrix<double> hessian = nt * n + options.energy_weight * energy;
  const Eigen::MatrixX2d targets = toMatrix(points);

  const int control_count = initial.controlPointCount();
  const int first_free = options.keep_end_points ? 1 : 0;
  const int free_count = control_count - (options.keep_end_points ? 2 : 0);
  if (free_count < 1) throw std::invalid_argument("elspiaFit: no de Boor point may move");
  const double mu =
      options.step > 0.0 ? options.step : optimalStep(hessian, first_free, free_count);

  Eigen::MatrixX2d control = toMatrix(initial.controlPoints());
  ElspiaResult result{initial, 0, false, 0.0};
  for (int iteration = 1; iteration <= options.max_iterations; ++iteration) {
    // Negative gradient (halved) of L: residuals pulled onto the de Boor points minus energy.
    Eigen::MatrixX2d update =
        mu * (nt * (targets - n * control) - options.energy_weight * (energy * control));
    if (options.keep_end_points) {
      update.row(0).setZero();
      update.row(control_count - 1).setZero();
    }
    control += update;
    result.iterations = iteration;
    if (!control.allFinite()) throw std::runtime_error("elspiaFit: diverged (step too large)");
    if (update.rowwise().norm().maxCoeff() <= options.tolerance) {
      result.converged = true;
      break;
    }
  }
  result.curve.setControlPoints(toPoints(control));
  const Eigen::MatrixX2d residual = n * control - targets;
  result.loss = residual.squaredNorm() +
                options.energy_weight * (control.transpose() * (energy * control)).trace();
  return result;
}

ElspiaResult refitOnKnots(const BSplineCurve& original, std::vector<double> knots,
                          const ElspiaOptions& options, int samples_per_span) {
  if (samples_per_span < 1) throw std::invalid_argument("refitOnKnots: need >= 1 sample/span");
  const int degree = original.degree();
  const int control_count = static_cast<int>(knots.size()) - degree - 1;
  if (control_count < degree + 1) {
    throw std::invalid_argument("refitOnKnots: too few knots for degree " + std::to_string(degree));
  }
  // Greville abscissae: where each de Boor point has the most influence.
  std::vector<Point2> start(control_count);
  for (int i = 0; i < control_count; ++i) {
    double sum = 0.0;
    for (int j = 1; j <= degree; ++j) sum += knots[i + j];
    start[i] = original.pointAt(sum / degree);
  }
  const BSplineCurve initial(degree, std::move(knots), std::move(start));
  if (initial.domainBegin() != original.domainBegin() ||
      initial.domainEnd() != original.domainEnd()) {
    throw std::invalid_argument("refitOnKnots: the new knots must span the original domain");
  }
  std::vector<double> parameters;
  std::vector<Point2> samples;
  const std::vector<double> breaks = initial.breakpoints();
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
    for (int i = 0; i < samples_per_span; ++i) {
      const double w = static_cast<double>(i) / samples_per_span;
      parameters.push_back((1.0 - w) * breaks[k] + w * breaks[k + 1]);
    }
  }
  parameters.push_back(breaks.back());
  for (double u : parameters) samples.push_back(original.pointAt(u));
  return elspiaFit(initial, samples, parameters, options);
}

}  // namespace bspline
}  // namespace vicc_glyphs
