#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "vicc_glyphs/bspline/knot_insertion.hpp"

namespace vicc_glyphs {
namespace bspline {
namespace {

BSplineCurve clampedCurve() {
  return BSplineCurve(3, {0, 0, 0, 0, 0.7, 1.5, 1.5, 2.6, 4, 4, 4, 4},
                      {{0, 0}, {1, 3}, {3, 4}, {5, 1}, {6, -2}, {8, 0}, {9, 4}, {12, 3}});
}

// Uniform, not clamped: the domain [t_3, t_6] does not start at a de Boor point.
BSplineCurve unclampedCurve() {
  return BSplineCurve(3, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9},
                      {{0, 0}, {2, 5}, {4, -1}, {6, 4}, {8, 0}, {10, 3}});
}

// Largest distance between the two curves at 1000 parameters across the common domain.
double maxDeviation(const BSplineCurve& a, const BSplineCurve& b) {
  double worst = 0.0;
  for (int i = 0; i < 1000; ++i) {
    const double w = i / 999.0;
    const double u = (1.0 - w) * a.domainBegin() + w * a.domainEnd();
    worst = std::max(worst, (a.pointAt(u) - b.pointAt(u)).norm());
  }
  return worst;
}

TEST(KnotInsertionTest, SingleInsertionKeepsTheCurve) {
  const BSplineCurve curve = clampedCurve();
  const BSplineCurve refined = insertKnot(curve, 2.0);
  EXPECT_EQ(refined.controlPointCount(), curve.controlPointCount() + 1);
  EXPECT_EQ(refined.knots().size(), curve.knots().size() + 1);
  EXPECT_EQ(refined.multiplicity(2.0), 1);
  EXPECT_LT(maxDeviation(curve, refined), 1e-9);
}

TEST(KnotInsertionTest, RepeatedAndExistingKnotsKeepTheCurve) {
  const BSplineCurve curve = clampedCurve();
  const BSplineCurve tripled = insertKnot(curve, 3.1, 3);
  EXPECT_EQ(tripled.multiplicity(3.1), 3);
  EXPECT_LT(maxDeviation(curve, tripled), 1e-9);
  // With multiplicity 3 = degree the curve passes through a de Boor point there.
  bool interpolated = false;
  for (const Point2& d : tripled.controlPoints()) {
    interpolated |= (d - curve.pointAt(3.1)).norm() < 1e-12;
  }
  EXPECT_TRUE(interpolated);

  const BSplineCurve raised = insertKnot(curve, 1.5);  // already double
  EXPECT_EQ(raised.multiplicity(1.5), 3);
  EXPECT_LT(maxDeviation(curve, raised), 1e-9);

  const BSplineCurve many = insertKnots(curve, {0.1, 0.2, 0.2, 3.999, 2.6});
  EXPECT_EQ(many.controlPointCount(), curve.controlPointCount() + 5);
  EXPECT_LT(maxDeviation(curve, many), 1e-9);
}

TEST(KnotInsertionTest, WorksOnUnclampedKnotVectorsIncludingTheDomainEnds) {
  const BSplineCurve curve = unclampedCurve();
  EXPECT_LT(maxDeviation(curve, insertKnot(curve, 4.25, 2)), 1e-9);
  EXPECT_LT(maxDeviation(curve, insertKnot(curve, 3.0, 3)), 1e-9);
  EXPECT_LT(maxDeviation(curve, insertKnot(curve, 6.0, 3)), 1e-9);
}

TEST(KnotInsertionTest, RaisingAllMultiplicitiesToTheDegreeKeepsTheCurve) {
  for (const BSplineCurve& curve : {clampedCurve(), unclampedCurve()}) {
    const BSplineCurve bezier = raiseMultiplicities(curve, 3);
    for (double u : curve.breakpoints()) EXPECT_GE(bezier.multiplicity(u), 3) << u;
    EXPECT_LT(maxDeviation(curve, bezier), 1e-9);
  }
}

// A clamped cubic of 400 de Boor points on a wavy path, knots 0, 1, ..., 396 inside.
BSplineCurve longCurve() {
  std::vector<double> knots(4, 0.0);
  for (int k = 1; k < 397; ++k) knots.push_back(k);
  knots.insert(knots.end(), 4, 397.0);
  std::vector<Point2> points;
  for (int i = 0; i < 400; ++i) points.emplace_back(i, 3.0 * std::sin(0.7 * i) + (i % 3));
  return BSplineCurve(3, knots, points);
}

// The splice cuts a long wave at many places at once (insertKnots on the whole list): each
// insertion must act on the refinement so far, also where the Boehm windows of neighbouring
// values overlap and where a value arrives out of order.
TEST(KnotInsertionTest, ManyInsertionsIntoALongCurveAreEachCountedAndKeepTheCurve) {
  const BSplineCurve curve = longCurve();
  std::vector<double> values;
  for (int k = 0; k < 60; ++k) {
    const double u = 390.3 - 6.5 * k;  // decreasing: every insertion lands before the last
    values.insert(values.end(), {u, u, u + 0.25});
  }
  values.insert(values.end(), {200.0, 0.5, 200.0});  // a knot raised to 3; the first span
  const BSplineCurve refined = insertKnots(curve, values);
  EXPECT_EQ(refined.controlPointCount(), curve.controlPointCount() + values.size());
  EXPECT_EQ(refined.knots().size(), curve.knots().size() + values.size());
  EXPECT_EQ(refined.multiplicity(390.3), 2);
  EXPECT_EQ(refined.multiplicity(390.55), 1);
  EXPECT_EQ(refined.multiplicity(200.0), 3);
  EXPECT_EQ(refined.multiplicity(0.5), 1);
  EXPECT_LT(maxDeviation(curve, refined), 1e-9);
  // One value at a time gives the same curve, bit for bit.
  BSplineCurve stepwise = curve;
  for (double u : values) stepwise = insertKnot(stepwise, u);
  EXPECT_EQ(stepwise.knots(), refined.knots());
  EXPECT_EQ(stepwise.controlPoints(), refined.controlPoints());
  // The multiplicity is checked against the refinement so far.
  EXPECT_THROW(insertKnots(curve, {150.5, 150.5, 150.5, 150.5}), std::invalid_argument);
}

TEST(KnotInsertionTest, RejectsKnotsOutsideTheDomainOrAboveTheAllowedMultiplicity) {
  const BSplineCurve curve = clampedCurve();
  EXPECT_THROW(insertKnot(curve, -0.1), std::invalid_argument);
  EXPECT_THROW(insertKnot(curve, 4.1), std::invalid_argument);
  EXPECT_THROW(insertKnot(curve, std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
  EXPECT_THROW(insertKnot(curve, 1.0, 0), std::invalid_argument);
  EXPECT_THROW(insertKnot(curve, 1.5, 2), std::invalid_argument);  // 2 + 2 > degree
  EXPECT_THROW(insertKnot(curve, 0.0), std::invalid_argument);     // clamped end is full
  EXPECT_THROW(raiseMultiplicities(curve, 4), std::invalid_argument);
}

}  // namespace
}  // namespace bspline
}  // namespace vicc_glyphs
