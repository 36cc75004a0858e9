#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "vicc_glyphs/bspline/arc_length.hpp"
#include "vicc_glyphs/bspline/bezier_conversion.hpp"

namespace vicc_glyphs {
namespace bspline {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A straight segment from (0, 0) to (10, 0) traversed with very uneven speed: x(u) is the exact
// arc length l(u).
BSplineCurve unevenLine() {
  return BSplineCurve(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0}, {0.1, 0}, {9, 0}, {10, 0}});
}
double lineX(double u) {
  const double v = 1.0 - u;
  return 3 * v * v * u * 0.1 + 3 * v * u * u * 9.0 + u * u * u * 10.0;
}

// Reference l(u) independent of the table: composite 5-point Gauss-Legendre on |s'|.
double referenceLength(const BSplineCurve& curve, double a, double b) {
  static const double nodes[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                                  0.9061798459386640};
  static const double weights[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                    0.4786286704993665, 0.2369268850561891};
  const int pieces = 2000;
  double total = 0.0;
  for (int k = 0; k < pieces; ++k) {
    const double lo = a + (b - a) * k / pieces;
    const double hi = a + (b - a) * (k + 1) / pieces;
    for (int q = 0; q < 5; ++q) {
      const double u = 0.5 * (lo + hi) + 0.5 * (hi - lo) * nodes[q];
      total += 0.5 * (hi - lo) * weights[q] * curve.derivativeAt(u).norm();
    }
  }
  return total;
}

BSplineCurve circle(double radius) {
  const double k = 0.5522847498 * radius;
  const std::vector<Point2> chain = {{radius, 0},   {radius, k},  {k, radius},  {0, radius},
                                     {-k, radius},  {-radius, k}, {-radius, 0}, {-radius, -k},
                                     {-k, -radius}, {0, -radius}, {k, -radius}, {radius, -k},
                                     {radius, 0}};
  return bezierChainToBSpline(chain).curve;
}

TEST(ArcLengthTest, StraightLineWithUnevenSpeedMatchesTheExactLength) {
  const BSplineCurve line = unevenLine();
  const ArcLengthTable table(line);
  EXPECT_NEAR(table.totalLength(), 10.0, 1e-12);  // chords of a straight line are exact
  double worst_length = 0.0;
  double worst_inverse = 0.0;
  for (int i = 0; i <= 997; ++i) {
    const double u = i / 997.0;
    worst_length = std::max(worst_length, std::abs(table.lengthAt(u) - lineX(u)));
    const double l = 10.0 * i / 997.0;
    worst_inverse = std::max(worst_inverse, std::abs(lineX(table.parameterAt(l)) - l));
  }
  RecordProperty("line_max_length_error", std::to_string(worst_length));
  EXPECT_LT(worst_length, 1e-3 * 10.0);
  EXPECT_LT(worst_inverse, 1e-3 * 10.0);
}

TEST(ArcLengthTest, CircleLengthIsWithinATenthOfAPercent) {
  const double radius = 25.0;
  const BSplineCurve curve = circle(radius);
  const ArcLengthTable table(curve);
  const double reference = referenceLength(curve, curve.domainBegin(), curve.domainEnd());
  // The four-arc Bezier circle is ~1e-4 longer than the true circle; the table is much closer
  // to the integral of |s'|.
  EXPECT_NEAR(reference, 2 * kPi * radius, 1e-3 * 2 * kPi * radius);
  EXPECT_NEAR(table.totalLength(), reference, 1e-3 * reference);
  double worst = 0.0;
  for (double u = 0.0; u <= 4.0; u += 0.0371) {
    worst = std::max(worst, std::abs(table.lengthAt(u) - referenceLength(curve, 0.0, u)));
  }
  RecordProperty("circle_max_relative_error", std::to_string(worst / reference));
  EXPECT_LT(worst, 1e-3 * reference);
  // A coarse table is measurably worse, so the check above has teeth.
  const ArcLengthTable coarse(curve, 2);
  EXPECT_GT(std::abs(coarse.totalLength() - reference), 1e-3 * reference);
}

TEST(ArcLengthTest, EquidistantParametersAreEquallySpacedAlongTheCurve) {
  const BSplineCurve line = unevenLine();
  const ArcLengthTable table(line);
  const std::vector<double> u = table.equidistantParameters(11);
  ASSERT_EQ(u.size(), 11u);
  EXPECT_DOUBLE_EQ(u.front(), 0.0);
  EXPECT_DOUBLE_EQ(u.back(), 1.0);
  for (int i = 0; i <= 10; ++i) EXPECT_NEAR(lineX(u[i]), i, 1e-2) << i;
  EXPECT_NEAR(table.lengthAt(table.parameterAt(3.3)), 3.3, 1e-9);
}

TEST(ArcLengthTest, ParametersOfSortedLengthsAreParameterAtOfEach) {
  const BSplineCurve curve = circle(3.0);
  const ArcLengthTable table(curve, 16);
  const double total = table.totalLength();
  // Before the start, ties, exact table entries, the end and past it: all clamped alike.
  std::vector<double> lengths = {-1.0, 0.0, 0.0, table.lengths()[5], 1e-9};
  for (int i = 1; i < 40; ++i) lengths.push_back(total * i / 40.0);
  lengths.insert(lengths.end(), {table.lengths()[60], total, total, total + 2.0});
  std::sort(lengths.begin(), lengths.end());
  const std::vector<double> parameters = table.parametersAt(lengths);
  ASSERT_EQ(parameters.size(), lengths.size());
  for (std::size_t i = 0; i < lengths.size(); ++i) {
    EXPECT_EQ(parameters[i], table.parameterAt(lengths[i])) << i;  // the same arithmetic
  }
  // A short run that starts far into the table.
  const std::vector<double> tail = {0.9 * total, 0.95 * total};
  EXPECT_EQ(table.parametersAt(tail)[1], table.parameterAt(0.95 * total));
  EXPECT_TRUE(table.parametersAt({}).empty());
}

TEST(ArcLengthTest, RejectsBadInput) {
  EXPECT_THROW(ArcLengthTable(unevenLine(), 0), std::invalid_argument);
  const ArcLengthTable table(unevenLine());
  EXPECT_THROW(table.lengthAt(std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
  EXPECT_THROW(table.parameterAt(std::numeric_limits<double>::infinity()), std::invalid_argument);
  EXPECT_THROW(table.equidistantParameters(1), std::invalid_argument);
  EXPECT_THROW(table.parametersAt({2.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(table.parametersAt({1.0, std::numeric_limits<double>::quiet_NaN()}),
               std::invalid_argument);
}

}  // namespace
}  // namespace bspline
}  // namespace vicc_glyphs
