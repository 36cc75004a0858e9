#pragma once
// A planar B-spline curve s(u) = sum_i d_i N_i^p(u) (thesis 2.5.2, Eq. 2.34): degree p, de Boor
// points d_0 .. d_n and a non-decreasing knot vector t_0 .. t_{n+p+1}. The curve is defined on
// the domain [t_p, t_{n+1}]. Coordinates follow diffusion_curve.hpp (pixels, y down).

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"
#include "vicc_glyphs/dci/flattening.hpp"

namespace vicc_glyphs {
namespace bspline {

/// The basis functions that do not vanish at a parameter: N_{first}, ..., N_{first+p} (or their
/// derivatives of a given order), as used for fitting matrices.
struct BasisRow {
  int first_index = 0;
  Eigen::VectorXd values;
};

/// BasisRow of a cubic: four values, no heap allocation.
struct CubicBasisRow {
  int first_index = 0;
  Eigen::Vector4d values = Eigen::Vector4d::Zero();
};

/// The knot span of v within the domain of a curve with `control_point_count` de Boor points
/// and `knots`: l with t_l <= v < t_{l+1}, or at the domain's end its last non-empty span.
/// BSplineCurve::findSpan after clamping; also for knot vectors being refined in place.
int knotSpan(const std::vector<double>& knots, int control_point_count, double v);

class BSplineCurve {
 public:
  /// Validates and stores the curve. Throws std::invalid_argument with a reason when the degree
  /// is below 1, there are fewer than degree + 1 de Boor points, the knot count is not
  /// points + degree + 1, knots decrease, a knot or point is not finite, the domain is empty,
  /// an interior knot has a multiplicity above the degree (the curve would break apart) or an
  /// end knot one above degree + 1.
  BSplineCurve(int degree, std::vector<double> knots, std::vector<Point2> control_points);

  /// A clamped (open) knot vector over [begin, end] with uniformly spaced interior knots, for
  /// `control_count` de Boor points: the curve starts at the first and ends at the last point.
  static std::vector<double> clampedUniformKnots(int degree, int control_count, double begin,
                                                 double end);

  int degree() const { return degree_; }
  const std::vector<double>& knots() const { return knots_; }
  const std::vector<Point2>& controlPoints() const { return control_points_; }
  int controlPointCount() const { return static_cast<int>(control_points_.size()); }

  /// Replaces the de Boor points keeping the knots; same validation as the constructor.
  void setControlPoints(std::vector<Point2> control_points);

  double domainBegin() const { return knots_[degree_]; }
  double domainEnd() const { return knots_[control_points_.size()]; }

  /// Index l of the knot span [t_l, t_{l+1}) with non-zero length that contains u, limited to
  /// the domain (the end of the domain belongs to the last span).
  int findSpan(double u) const;
  /// How often the knot value u occurs in the knot vector (exact comparison).
  int multiplicity(double u) const;
  /// The distinct knot values within the domain, including its ends: the parameters where the
  /// polynomial pieces join.
  std::vector<double> breakpoints() const;

  /// Curve point by the de Boor algorithm (Eq. 2.40); u is clamped to the domain.
  Point2 pointAt(double u) const;
  /// Derivative d^order s / du^order (order >= 0) from the derivative de Boor points of
  /// Eq. 2.42; zero above the degree. u is clamped to the domain.
  Point2 derivativeAt(double u, int order = 1) const;
  /// The p + 1 basis functions (or their derivatives of `order`) that may be non-zero at u.
  BasisRow basisAt(double u, int order = 0) const;
  /// basisAt for each of `parameters` of a cubic curve, parameters that must not decrease
  /// (std::invalid_argument otherwise, or for another degree): the spans are walked in order.
  std::vector<CubicBasisRow> cubicBasisAt(const std::vector<double>& parameters) const;

  /// Samples `count` >= 2 points at parameters equally spaced over the domain.
  std::vector<Point2> sample(int count) const;
  /// `per_span` >= 1 points on each polynomial piece (between breakpoints) at equally spaced
  /// parameters from its start, then the domain end; their parameters go to `parameters`. The
  /// points are pointAt's (up to round-off from 6 per piece on, as pointsAt's); the pieces are
  /// walked in order instead of searched per point.
  std::vector<Point2> sampleSpans(int per_span, std::vector<double>& parameters) const;
  /// A cubic's polynomial pieces flattened as the renderer flattens the Bezier segments they
  /// become (dci/flattening.hpp): each piece in flatteningPieces uniform steps of its Bezier
  /// points, then the domain end; their parameters go to `parameters`. Throws
  /// std::invalid_argument for another degree.
  std::vector<Point2> flattenSpans(std::vector<double>& parameters,
                                   const Flattening& flattening = {}) const;
  /// pointAt for each of `parameters`, which must not decrease (std::invalid_argument
  /// otherwise): the knot spans are walked in order instead of searched per point.
  std::vector<Point2> pointsAt(const std::vector<double>& parameters) const;
  /// True when the first and last curve points coincide within `tolerance`.
  bool isClosed(double tolerance = 1e-9) const;

 private:
  void validate() const;
  // Inline: called per point of every sampling (a call through the library's PLT cost more
  // than the clamp).
  double clampToDomain(double u) const {
    if (!std::isfinite(u)) failNotFinite();
    return std::clamp(u, domainBegin(), domainEnd());
  }
  [[noreturn]] static void failNotFinite();
  /// findSpan(v) for a v in the domain not below the one whose span was `span` (-1: none yet).
  int nextSpan(double v, int span) const;
  /// derivativeAt for a v in the domain whose knot span findSpan(v) is `span`.
  Point2 evaluateOn(double v, int span, int order) const;
  /// pointAt of the parameters[first ..] that lie on knot span `span` (which holds
  /// parameters[first]), appended to `points`; returns the index after the last. A cubic span
  /// with several of them is evaluated in Bezier form.
  std::size_t pointsOnSpan(const std::vector<double>& parameters, std::size_t first, int span,
                           std::vector<Point2>& points) const;

  int degree_;
  std::vector<double> knots_;
  std::vector<Point2> control_points_;
};

}  // namespace bspline
}  // namespace vicc_glyphs
