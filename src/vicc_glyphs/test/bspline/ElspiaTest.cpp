#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>

#include "vicc_glyphs/bspline/arc_length.hpp"
#include "vicc_glyphs/bspline/curve_energy.hpp"
#include "vicc_glyphs/bspline/elspia.hpp"
#include "vicc_glyphs/bspline/fitting.hpp"

namespace vicc_glyphs {
namespace bspline {
namespace {

// Points on a wiggly path and a straight, badly placed start curve with 10 de Boor points.
struct Problem {
  std::vector<double> parameters;
  std::vector<Point2> points;
  BSplineCurve start{3, BSplineCurve::clampedUniformKnots(3, 10, 0.0, 1.0),
                     std::vector<Point2>(10, Point2::Zero())};
};

Problem wigglyProblem() {
  Problem problem;
  for (int i = 0; i <= 120; ++i) {
    const double u = i / 120.0;
    problem.parameters.push_back(u);
    problem.points.emplace_back(40.0 * u, 5.0 * std::sin(9.0 * u) + 1.5 * std::sin(31.0 * u));
  }
  std::vector<Point2> line;
  for (int i = 0; i < 10; ++i) line.emplace_back(40.0 * i / 9.0, 0.0);
  problem.start.setControlPoints(line);
  return problem;
}

// Direct solution of the ELSPIA fixed point (N^T N + omega E) D = N^T P.
std::vector<Point2> directSolution(const Problem& problem, double omega) {
  const Eigen::MatrixXd n = collocationMatrix(problem.start, problem.parameters);
  const Eigen::MatrixXd e = energyMatrix(problem.start, 1);
  Eigen::MatrixX2d p(problem.points.size(), 2);
  for (std::size_t i = 0; i < problem.points.size(); ++i) p.row(i) = problem.points[i].transpose();
  const Eigen::MatrixX2d d = (n.transpose() * n + omega * e).ldlt().solve(n.transpose() * p);
  std::vector<Point2> result(d.rows());
  for (int i = 0; i < d.rows(); ++i) result[i] = d.row(i).transpose();
  return result;
}

double maxDistance(const std::vector<Point2>& a, const std::vector<Point2>& b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, (a[i] - b[i]).norm());
  return worst;
}

TEST(ElspiaTest, WithoutEnergyConvergesToTheLeastSquaresFit) {
  const Problem problem = wigglyProblem();
  const ElspiaResult result = elspiaFit(problem.start, problem.points, problem.parameters);
  EXPECT_TRUE(result.converged);
  const BSplineCurve direct =
      leastSquaresFit(3, problem.start.knots(), problem.points, problem.parameters);
  EXPECT_LT(maxDistance(result.curve.controlPoints(), direct.controlPoints()), 1e-6);
  RecordProperty("lspia_iterations", result.iterations);
}

TEST(ElspiaTest, LossDecreasesMonotonicallyTowardsThePoints) {
  const Problem problem = wigglyProblem();
  ElspiaOptions options;
  options.energy_weight = 0.01;
  double previous = std::numeric_limits<double>::infinity();
  for (int iterations : {1, 2, 4, 8, 16, 64, 256}) {
    options.max_iterations = iterations;
    const double loss = elspiaFit(problem.start, problem.points, problem.parameters, options).loss;
    EXPECT_LT(loss, previous) << iterations;
    previous = loss;
  }
}

TEST(ElspiaTest, WithEnergyConvergesToTheRegularisedSolution) {
  const Problem problem = wigglyProblem();
  ElspiaOptions options;
  options.energy_weight = 0.05;
  const ElspiaResult result = elspiaFit(problem.start, problem.points, problem.parameters, options);
  EXPECT_TRUE(result.converged);
  EXPECT_LT(maxDistance(result.curve.controlPoints(), directSolution(problem, 0.05)), 1e-6);
}

TEST(ElspiaTest, StretchingTermShortensTheCurveAndLowersItsEnergy) {
  const Problem problem = wigglyProblem();
  const BSplineCurve plain = elspiaFit(problem.start, problem.points, problem.parameters).curve;
  ElspiaOptions options;
  options.energy_weight = 0.2;
  const BSplineCurve fair =
      elspiaFit(problem.start, problem.points, problem.parameters, options).curve;
  EXPECT_LT(curveEnergy(fair, 1), 0.95 * curveEnergy(plain, 1));
  EXPECT_LT(ArcLengthTable(fair).totalLength(), ArcLengthTable(plain).totalLength());
  // The fairer curve follows the points less closely.
  double plain_residual = 0.0;
  double fair_residual = 0.0;
  for (std::size_t i = 0; i < problem.points.size(); ++i) {
    plain_residual += (plain.pointAt(problem.parameters[i]) - problem.points[i]).squaredNorm();
    fair_residual += (fair.pointAt(problem.parameters[i]) - problem.points[i]).squaredNorm();
  }
  EXPECT_GT(fair_residual, plain_residual);
}

TEST(ElspiaTest, EnergyMatrixReproducesTheCurveEnergy) {
  const Problem problem = wigglyProblem();
  const BSplineCurve curve = elspiaFit(problem.start, problem.points, problem.parameters).curve;
  for (int order : {1, 2}) {
    const Eigen::SparseMatrix<double> gram = energyMatrix(curve, order);
    double quadratic = 0.0;
    for (int axis = 0; axis < 2; ++axis) {
      Eigen::VectorXd d(curve.controlPointCount());
      for (int i = 0; i < d.size(); ++i) d[i] = curve.controlPoints()[i][axis];
      quadratic += d.dot(gram * d);
    }
    EXPECT_NEAR(quadratic, curveEnergy(curve, order), 1e-9 * quadratic) << order;
  }
  // A straight line at unit speed over [0, 1] has stretching energy 1.
  const BSplineCurve line(3, {0, 0, 0, 0, 1, 1, 1, 1},
                          {{0, 0}, {1.0 / 3, 0}, {2.0 / 3, 0}, {1, 0}});
  EXPECT_NEAR(curveEnergy(line, 1), 1.0, 1e-12);
  EXPECT_NEAR(curveEnergy(line, 2), 0.0, 1e-12);
}

TEST(ElspiaTest, RefitOnFinerKnotsKeepsTheShapeAndEndPoints) {
  const BSplineCurve original(3, {0, 0, 0, 0, 1, 2, 2, 3, 3, 3, 3},
                              {{0, 0}, {3, 6}, {7, 7}, {10, 1}, {14, -2}, {18, 3}, {0.0, 0.0}});
  ASSERT_TRUE(original.isClosed());
  // Every old knot stays (with its multiplicity), so the original is exactly representable.
  ElspiaOptions options;
  options.keep_end_points = true;
  options.max_iterations = 20000;
  options.tolerance = 1e-12;
  const ElspiaResult refit =
      refitOnKnots(original, {0, 0, 0, 0, 0.5, 1, 1.5, 2, 2, 2.5, 3, 3, 3, 3}, options);
  EXPECT_TRUE(refit.converged);
  EXPECT_TRUE(refit.curve.isClosed(1e-12));
  double worst = 0.0;
  for (int i = 0; i <= 1000; ++i) {
    worst = std::max(
        worst, (refit.curve.pointAt(3.0 * i / 1000) - original.pointAt(3.0 * i / 1000)).norm());
  }
  EXPECT_LT(worst, 1e-6);
}

TEST(ElspiaTest, RejectsInvalidOptionsAndData) {
  const Problem problem = wigglyProblem();
  ElspiaOptions negative;
  negative.energy_weight = -1.0;
  EXPECT_THROW(elspiaFit(problem.start, problem.points, problem.parameters, negative),
               std::invalid_argument);
  ElspiaOptions no_iterations;
  no_iterations.max_iterations = 0;
  EXPECT_THROW(elspiaFit(problem.start, problem.points, problem.parameters, no_iterations),
               std::invalid_argument);
  EXPECT_THROW(elspiaFit(problem.start, problem.points, {0.5}), std::invalid_argument);
  EXPECT_THROW(elspiaFit(problem.start, {}, {}), std::invalid_argument);
  EXPECT_THROW(refitOnKnots(problem.start, {0, 0, 0, 0, 2, 2, 2, 2}), std::invalid_argument);
}

}  // namespace
}  // namespace bspline
}  // namespace vicc_glyphs
