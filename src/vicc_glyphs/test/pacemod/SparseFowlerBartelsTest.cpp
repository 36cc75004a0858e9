// The banded Fowler-Bartels against the toolkit's dense one (the same minimum-norm de Boor
// offsets), with its rows in any order, and its refusals.

#include "vicc_glyphs/pacemod/sparse_fowler_bartels.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

namespace vicc_glyphs {
namespace pacemod {
namespace {

using bspline::BSplineCurve;
using bspline::CurveConstraint;

BSplineCurve wavyCurve(int control_points) {
  std::vector<Point2> points;
  for (int i = 0; i < control_points; ++i) points.emplace_back(4.0 * i, 3.0 * std::sin(0.7 * i));
  return BSplineCurve(3, BSplineCurve::clampedUniformKnots(3, control_points, 0.0, 40.0), points);
}

// Positions a knot span or so apart, a few tangents, and the ends: rows that meet in N N^T,
// shuffled so that they come out of order along the curve (as PACEMOD's seam and corner rows).
std::vector<CurveConstraint> scatteredConstraints(const BSplineCurve& curve) {
  std::vector<CurveConstraint> constraints;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> move(-1.5, 1.5);
  for (double u = 0.0; u <= 40.0; u += 1.3) {
    constraints.push_back({u, curve.pointAt(u) + Point2(move(random), move(random)), 0});
  }
  for (double u : {0.0, 7.15, 22.4}) {
    constraints.push_back({u, curve.derivativeAt(u, 1) + Point2(move(random), 0.0), 1});
  }
  std::shuffle(constraints.begin(), constraints.end(), random);
  return constraints;
}

TEST(SparseFowlerBartelsTest, GivesTheDenseMinimumNormOffsetsForRowsInAnyOrder) {
  const BSplineCurve curve = wavyCurve(48);
  const std::vector<CurveConstraint> constraints = scatteredConstraints(curve);
  ASSERT_GT(constraints.size(), 30u);
  const BSplineCurve sparse = sparseFowlerBartels(curve, constraints);
  const BSplineCurve dense = bspline::fowlerBartelsModify(curve, constraints);
  ASSERT_EQ(sparse.controlPointCount(), dense.controlPointCount());
  for (int i = 0; i < sparse.controlPointCount(); ++i) {
    EXPECT_LT((sparse.controlPoints()[i] - dense.controlPoints()[i]).norm(), 1e-9) << i;
  }
  for (const CurveConstraint& c : constraints) {
    EXPECT_LT((sparse.derivativeAt(c.parameter, c.derivative_order) - c.target).norm(), 1e-9)
        << c.parameter << " order " << c.derivative_order;
  }
}

TEST(SparseFowlerBartelsTest, RejectsContradictoryOrCrowdedConstraintsAndBadInput) {
  const BSplineCurve curve = wavyCurve(20);
  // Five positions inside one knot span: only four de Boor points act there (a band of 5 rows,
  // singular).
  std::vector<CurveConstraint> crowded;
  for (int i = 0; i < 5; ++i) crowded.push_back({10.1 + 0.15 * i, Point2(20 + i, 2), 0});
  EXPECT_THROW(sparseFowlerBartels(curve, crowded), std::invalid_argument);
  // Thousands in one span: refused before a band that wide is set up.
  std::vector<CurveConstraint> swarm;
  for (int i = 0; i < 2000; ++i) swarm.push_back({10.0 + 2.0 * i / 2000, Point2(i, 0), 0});
  EXPECT_THROW(sparseFowlerBartels(curve, swarm), std::invalid_argument);
  // The same point asked to be in two places; outside the domain; not finite; a negative order.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<std::vector<CurveConstraint>> refused{
      {{4.0, Point2(0, 0), 0}, {4.0, Point2(1, 0), 0}},
      {{41.0, Point2(0, 0), 0}},
      {{nan, Point2(0, 0), 0}},
      {{4.0, Point2(nan, 0), 0}},
      {{4.0, Point2(0, 0), -1}}};
  for (std::size_t k = 0; k < refused.size(); ++k) {
    EXPECT_THROW(sparseFowlerBartels(curve, refused[k]), std::invalid_argument) << k;
  }
  EXPECT_EQ(sparseFowlerBartels(curve, {}).controlPoints(), curve.controlPoints());
}

}  // namespace
}  // namespace pacemod
}  // namespace vicc_glyphs
