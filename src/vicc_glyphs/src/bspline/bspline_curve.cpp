#include "vicc_glyphs/bspline/bspline_curve.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace vicc_glyphs {
namespace bspline {
namespace {

[[noreturn]] void fail(const std::string& reason) {
  throw std::invalid_argument("BSplineCurve: " + reason);
}

// Derivative of `order` on the knot span `span` from the p + 1 de Boor values that act there
// (local[j] belongs to index span - p + j). First the derivative de Boor points of Eq. 2.42 are
// formed `order` times, then the de Boor recursion of Eq. 2.40 runs with the lowered degree.
// Templated so that the same code yields curve points (Point2) and basis functions (a vector of
// unit coefficients). kDegree and kOrder >= 0 fix the degree and order at compile time (the
// loops unroll; the operations and their order stay the same); -1 takes `degree`, `derivative`.
template <int kDegree = -1, int kOrder = -1, typename Value>
Value evaluateOnSpan(const std::vector<double>& t, int degree, int span, Value* local, double u,
                     int derivative) {
  const int p = kDegree >= 0 ? kDegree : degree;
  const int order = kOrder >= 0 ? kOrder : derivative;
  if (order > p) return Value(local[0] * 0.0);
  for (int r = 1; r <= order; ++r) {
    for (int j = p; j >= r; --j) {
      const int i = span - p + j;
      const double scale = static_cast<double>(p - r + 1) / (t[i + p - r + 1] - t[i]);
      local[j] = scale * (local[j] - local[j - 1]);
    }
  }
  const int q = p - order;
  for (int k = 1; k <= q; ++k) {
    for (int j = p; j >= order + k; --j) {
      const int i = span - p + j;
      const double alpha = (u - t[i]) / (t[i + q + 1 - k] - t[i]);
      local[j] = (1.0 - alpha) * local[j - 1] + alpha * local[j];
    }
  }
  return local[p];
}

// Evaluating with unit coefficient vectors yields all p + 1 basis values at once; `unit` holds
// p + 1 zero vectors of at least p + 1 entries.
template <int kDegree = -1, typename Vector>
Vector unitBasis(const std::vector<double>& t, int p, int span, Vector* unit, double u, int order) {
  for (int j = 0; j <= p; ++j) unit[j][j] = 1.0;
  return evaluateOnSpan<kDegree>(t, p, span, unit, u, order);
}

// Degrees up to this are evaluated on fixed-size stack arrays (no heap allocation).
constexpr int kStackDegree = 7;

}  // namespace

BSplineCurve::BSplineCurve(int degree, std::vector<double> knots,
                           std::vector<Point2> control_points)
    : degree_(degree), knots_(std::move(knots)), control_points_(std::move(control_points)) {
  validate();
}

std::vector<double> BSplineCurve::clampedUniformKnots(int degree, int control_count, double begin,
                                                      double end) {
  if (degree < 1 || control_count < degree + 1 || !(begin < end)) {
    fail("clampedUniformKnots needs degree >= 1, at least degree + 1 points and begin < end");
  }
  std::vector<double> knots(control_count + degree + 1);
  const int interior = control_count - degree - 1;
  for (int i = 0; i <= degree; ++i) {
    knots[i] = begin;
    knots[knots.size() - 1 - i] = end;
  }
  for (int i = 1; i <= interior; ++i) {
    knots[degree + i] = begin + (end - begin) * i / (interior + 1);
  }
  return knots;
}

void BSplineCurve::setControlPoints(std::vector<Point2> control_points) {
  std::swap(control_points_, control_points);
  try {
    validate();
  } catch (...) {
    std::swap(control_points_, control_points);  // keep the curve valid on failure
    throw;
  }
}

void BSplineCurve::validate() const {
  const int p = degree_;
  const int n_points = static_cast<int>(control_points_.size());
  if (p < 1) fail("degree must be at least 1, got " + std::to_string(p));
  if (n_points < p + 1) {
    fail("degree " + std::to_string(p) + " needs at least " + std::to_string(p + 1) +
         " de Boor points, got " + std::to_string(n_points));
  }
  if (static_cast<int>(knots_.size()) != n_points + p + 1) {
    fail("expected " + std::to_string(n_points + p + 1) + " knots (points + degree + 1), got " +
         std::to_string(knots_.size()));
  }
  for (std::size_t i = 0; i < control_points_.size(); ++i) {
    if (!control_points_[i].allFinite()) fail("de Boor point " + std::to_string(i) + " not finite");
  }
  for (std::size_t i = 0; i < knots_.size(); ++i) {
    if (!std::isfinite(knots_[i])) fail("knot " + std::to_string(i) + " is not finite");
    if (i > 0 && knots_[i] < knots_[i - 1]) fail("knots decrease at index " + std::to_string(i));
  }
  if (!(domainBegin() < domainEnd())) fail("empty domain [t_p, t_{n+1}]");
  for (std::size_t i = 0; i < knots_.size();) {
    std::size_t j = i;
    while (j < knots_.size() && knots_[j] == knots_[i]) ++j;
    const int count = static_cast<int>(j - i);
    const bool interior = knots_[i] > domainBegin() && knots_[i] < domainEnd();
    if (count > (interior ? p : p + 1)) {
      std::ostringstream reason;
      reason << "knot " << knots_[i] << " occurs " << count << " times; at most "
             << (interior ? p : p + 1) << " allowed " << (interior ? "inside" : "at the ends of")
             << " the domain";
      fail(reason.str());
    }
    i = j;
  }
}

void BSplineCurve::failNotFinite() { fail("curve parameter is not finite"); }

int knotSpan(const std::vector<double>& knots, int control_point_count, double v) {
  const int n = control_point_count - 1;
  if (v >= knots[n + 1]) {
    int l = n;
    while (knots[l] == knots[l + 1]) --l;  // terminates: the domain is not empty
    return l;
  }
  const auto upper = std::upper_bound(knots.begin(), knots.begin() + n + 2, v);
  return static_cast<int>(upper - knots.begin()) - 1;
}

int BSplineCurve::findSpan(double u) const {
  return knotSpan(knots_, controlPointCount(), clampToDomain(u));
}

int BSplineCurve::nextSpan(double v, int span) const {
  // The first is searched, and so is the domain's end (findSpan's special case: it belongs to
  // the last span); the others are walked to.
  if (span < 0 || v >= domainEnd()) return findSpan(v);
  while (knots_[span + 1] <= v) ++span;  // findSpan: the last knot <= v
  return span;
}

int BSplineCurve::multiplicity(double u) const {
  const auto range = std::equal_range(knots_.begin(), knots_.end(), u);  // knots are sorted
  return static_cast<int>(range.second - range.first);
}

std::vector<double> BSplineCurve::breakpoints() const {
  std::vector<double> values;
  for (std::size_t i = degree_; i < control_points_.size() + 1; ++i) {
    if (values.empty() || knots_[i] != values.back()) values.push_back(knots_[i]);
  }
  return values;
}

Point2 BSplineCurve::pointAt(double u) const { return derivativeAt(u, 0); }

Point2 BSplineCurve::derivativeAt(double u, int order) const {
  if (order < 0) fail("derivative order must not be negative");
  const double v = clampToDomain(u);
  return evaluateOn(v, findSpan(v), order);
}

Point2 BSplineCurve::evaluateOn(double v, int span, int order) const {
  const auto first = control_points_.begin() + (span - degree_);
  if (degree_ == 3 && order <= 1) {  // the common cases: cubic curve points and tangents
    std::array<Point2, 4> local;
    std::copy(first, first + 4, local.begin());
    return order == 0 ? evaluateOnSpan<3, 0>(knots_, 3, span, local.data(), v, 0)
                      : evaluateOnSpan<3, 1>(knots_, 3, span, local.data(), v, 1);
  }
  // Curves are evaluated millions of times per glyph: no heap allocation for usual degrees.
  if (degree_ <= kStackDegree) {
    std::array<Point2, kStackDegree + 1> local;
    std::copy(first, first + degree_ + 1, local.begin());
    return evaluateOnSpan(knots_, degree_, span, local.data(), v, order);
  }
  std::vector<Point2> local(first, first + degree_ + 1);
  return evaluateOnSpan(knots_, degree_, span, local.data(), v, order);
}

BasisRow BSplineCurve::basisAt(double u, int order) const {
  if (order < 0) fail("derivative order must not be negative");
  const double v = clampToDomain(u);
  const int span = findSpan(v);
  BasisRow row;
  row.first_index = span - degree_;
  // Fitting matrices take a row per sample: no heap allocation for usual degrees.
  if (degree_ == 3) {  // the common case: unrolled
    std::array<Eigen::Vector4d, 4> unit;
    unit.fill(Eigen::Vector4d::Zero());
    row.values = unitBasis<3>(knots_, 3, span, unit.data(), v, order);
  } else if (degree_ <= kStackDegree) {
    // Fixed size (unrolled): the unused tail stays zero, the p + 1 values are the same.
    using Small = Eigen::Matrix<double, kStackDegree + 1, 1>;
    std::array<Small, kStackDegree + 1> unit;
    unit.fill(Small::Zero());
    row.values = unitBasis(knots_, degree_, span, unit.data(), v, order).head(degree_ + 1);
  } else {
    std::vector<Eigen::VectorXd> unit(degree_ + 1, Eigen::VectorXd::Zero(degree_ + 1));
    row.values = unitBasis(knots_, degree_, span, unit.data(), v, order);
  }
  return row;
}

std::vector<CubicBasisRow> BSplineCurve::cubicBasisAt(const std::vector<double>& parameters) const {
  if (degree_ != 3) fail("cubicBasisAt needs a cubic, got degree " + std::to_string(degree_));
  std::vector<CubicBasisRow> rows(parameters.size());
  int span = -1;
  std::array<Eigen::Vector4d, 4> unit;
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    const double v = clampToDomain(parameters[i]);
    if (i > 0 && parameters[i] < parameters[i - 1]) {
      fail("cubicBasisAt needs parameters that do not decrease");
    }
    span = nextSpan(v, span);
    unit.fill(Eigen::Vector4d::Zero());
    rows[i] = {span - 3, unitBasis<3>(knots_, 3, span, unit.data(), v, 0)};
  }
  return rows;
}

std::vector<Point2> BSplineCurve::sample(int count) const {
  if (count < 2) fail("sampling needs at least 2 points");
  std::vector<Point2> points(count);
  for (int i = 0; i < count; ++i) {
    const double w = static_cast<double>(i) / (count - 1);
    points[i] = pointAt((1.0 - w) * domainBegin() + w * domainEnd());
  }
  return points;
}

std::vector<Point2> BSplineCurve::sampleSpans(int per_span, std::vector<double>& parameters) const {
  if (per_span < 1) fail("sampling needs at least 1 point per knot span");
  const std::vector<double> breaks = breakpoints();
  std::vector<Point2> points;
  // Reserved: grown step by step, a high-frequency wave's polygon (tens of thousands of points)
  // would touch fresh memory several times over.
  points.reserve((breaks.size() - 1) * per_span + 1);
  parameters.clear();
  parameters.reserve(points.capacity());
  int span = degree_;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const std::size_t first = parameters.size();
    for (int k = 0; k < per_span; ++k) {
      parameters.push_back(breaks[i] + (breaks[i + 1] - breaks[i]) * k / per_span);
    }
    // The piece's points by pointsOnSpan: many per piece in its Bezier form.
    span = nextSpan(clampToDomain(parameters[first]), span);
    pointsOnSpan(parameters, first, span, points);
  }
  parameters.push_back(breaks.back());
  points.push_back(pointAt(breaks.back()));
  return points;
}

std::vector<Point2> BSplineCurve::flattenSpans(std::vector<double>& parameters,
                                               const Flattening& flattening) const {
  if (degree_ != 3) fail("flattening needs a cubic curve");
  const std::vector<double> breaks = breakpoints();
  const std::size_t pieces = breaks.size() - 1;
  // Each polynomial piece's Bezier points, from its ends and end derivatives (of this piece's
  // polynomial: at a corner the next piece's derivative differs).
  std::vector<std::array<Point2, 4>> beziers(pieces);
  int span = degree_;
  for (std::size_t i = 0; i < pieces; ++i) {
    const double u0 = breaks[i], u1 = breaks[i + 1], h = u1 - u0;
    span = nextSpan(u0, span);
    const Point2 p0 = evaluateOn(u0, span, 0), p1 = evaluateOn(u1, span, 0);
    beziers[i] = {p0, p0 + h / 3.0 * evaluateOn(u0, span, 1),
                  p1 - h / 3.0 * evaluateOn(u1, span, 1), p1};
  }
  std::vector<Point2> chain{beziers.front()[0]};  // the Bezier chain the curve becomes
  for (const auto& b : beziers) chain.insert(chain.end(), b.begin() + 1, b.end());
  const std::vector<char> beside_fold = segmentsBesideFolds(chain);
  std::vector<Point2> points;
  parameters.clear();
  for (std::size_t i = 0; i < pieces; ++i) {
    const Point2* b = beziers[i].data();
    const int steps = flatteningPieces(b, beside_fold[i], flattening);
    for (int k = 0; k < steps; ++k) {
      points.push_back(bezierPoint(b, static_cast<double>(k) / steps));
      parameters.push_back(breaks[i] + (breaks[i + 1] - breaks[i]) * k / steps);
    }
  }
  parameters.push_back(breaks.back());
  points.push_back(pointAt(breaks.back()));
  return points;
}

std::vector<Point2> BSplineCurve::pointsAt(const std::vector<double>& parameters) const {
  std::vector<Point2> points;
  points.reserve(parameters.size());
  for (std::size_t i = 1; i < parameters.size(); ++i) {
    if (parameters[i] < parameters[i - 1]) fail("pointsAt needs parameters that do not decrease");
  }
  int span = -1;
  for (std::size_t i = 0; i < parameters.size();) {
    span = nextSpan(clampToDomain(parameters[i]), span);
    i = pointsOnSpan(parameters, i, span, points);
  }
  return points;
}

std::size_t BSplineCurve::pointsOnSpan(const std::vector<double>& parameters, std::size_t first,
                                       int span, std::vector<Point2>& points) const {
  // The span ending at the domain's end also holds the end (findSpan's special case) and what
  // lies beyond; what lies before the domain is on the first span, which holds `first`. A
  // non-finite parameter is refused by clampToDomain, below or where the next run starts.
  const bool last_span = knots_[span + 1] >= domainEnd();
  const auto on_span = [&](std::size_t i) {
    return i < parameters.size() && (last_span || parameters[i] < knots_[span + 1]);
  };
  std::size_t end = first + 1;
  while (on_span(end)) ++end;
  // From this many points on, the span's Bezier points (two ends and two end derivatives, of
  // this span's polynomial) and Bernstein's form cost less than de Boor's scheme per point, which
  // divides by knot differences six times: OffsetFit samples the icon's contour dozens of times
  // per contour span. The same points up to round-off (~1e-13 px).
  constexpr std::size_t kBezierFrom = 6;
  if (degree_ != 3 || end - first < kBezierFrom) {
    for (std::size_t i = first; i < end; ++i) {
      points.push_back(evaluateOn(clampToDomain(parameters[i]), span, 0));
    }
    return end;
  }
  const double u0 = knots_[span], u1 = knots_[span + 1], inverse_length = 1.0 / (u1 - u0);
  const Point2 p0 = evaluateOn(u0, span, 0), p1 = evaluateOn(u1, span, 0);
  const Point2 bezier[4] = {p0, p0 + (u1 - u0) / 3.0 * evaluateOn(u0, span, 1),
                            p1 - (u1 - u0) / 3.0 * evaluateOn(u1, span, 1), p1};
  for (std::size_t i = first; i < end; ++i) {
    points.push_back(bezierPoint(bezier, (clampToDomain(parameters[i]) - u0) * inverse_length));
  }
  return end;
}

bool BSplineCurve::isClosed(double tolerance) const {
  return (pointAt(domainBegin()) - pointAt(domainEnd())).norm() <= tolerance;
}

}  // namespace bspline
}  // namespace vicc_glyphs
