#include "bezier_refit.hpp"

#include <algorithm>
#include <cmath>

#include "cubic_bezier.hpp"

namespace vicc_glyphs {
namespace io_detail {
namespace {

constexpr int kMaxDepth = 24;
constexpr int kNewtonIterations = 4;

using Cubic = CubicBezier;

Point2 unit(const Point2& v) {
  const double n = v.norm();
  return n > 0.0 ? Point2(v / n) : Point2(Point2::Zero());
}

class Fitter {
 public:
  Fitter(const std::vector<Point2>& p, double tolerance, std::vector<Point2>& out)
      : p_(p), tolerance_(tolerance), out_(out) {}

  int fit(const Point2& t0, const Point2& t1) {
    fitRange(0, static_cast<int>(p_.size()) - 1, t0, t1, 0);
    return segments_;
  }

 private:
  void emit(const Cubic& c) {
    out_.insert(out_.end(), {c.b[1], c.b[2], c.b[3]});
    ++segments_;
  }

  void emitLine(int first, int last) {
    const Point2 a = p_[first], b = p_[last];
    emit({{a, a + (b - a) / 3.0, a + 2.0 * (b - a) / 3.0, b}});
  }

  std::vector<double> chordParameters(int first, int last) const {
    std::vector<double> u(last - first + 1, 0.0);
    for (int i = first + 1; i <= last; ++i)
      u[i - first] = u[i - first - 1] + (p_[i] - p_[i - 1]).norm();
    const double total = u.back();
    for (double& v : u) v = total > 0.0 ? v / total : 0.0;
    return u;
  }

  // Least squares for the two tangent lengths (Schneider's 2 x 2 system); the Wu-Barsky
  // heuristic (a third of the chord) where the system is degenerate or gives a bad sign.
  Cubic generate(int first, int last, const std::vector<double>& u, const Point2& t0,
                 const Point2& t1) const {
    double c00 = 0, c01 = 0, c11 = 0, x0 = 0, x1 = 0;
    const Point2 a = p_[first], b = p_[last];
    for (int i = first; i <= last; ++i) {
      const double t = u[i - first], s = 1 - t;
      const Point2 a0 = t0 * 3 * s * s * t, a1 = t1 * 3 * s * t * t;
      c00 += a0.dot(a0);
      c01 += a0.dot(a1);
      c11 += a1.dot(a1);
      const Point2 rest = p_[i] - (s * s * s + 3 * s * s * t) * a - (3 * s * t * t + t * t * t) * b;
      x0 += a0.dot(rest);
      x1 += a1.dot(rest);
    }
    const double det = c00 * c11 - c01 * c01;
    const double chord = (b - a).norm();
    double alpha0 = std::abs(det) > 1e-12 ? (x0 * c11 - x1 * c01) / det : 0.0;
    double alpha1 = std::abs(det) > 1e-12 ? (c00 * x1 - c01 * x0) / det : 0.0;
    if (!(alpha0 > 1e-6 * chord) || !(alpha1 > 1e-6 * chord) || alpha0 > 2 * chord ||
        alpha1 > 2 * chord) {
      alpha0 = alpha1 = chord / 3.0;
    }
    return {{a, a + alpha0 * t0, b + alpha1 * t1, b}};
  }

  double maxError(const Cubic& c, int first, int last, const std::vector<double>& u,
                  int& worst) const {
    double error = 0.0;
    worst = (first + last) / 2;
    for (int i = first + 1; i < last; ++i) {
      const double e = (c.at(u[i - first]) - p_[i]).squaredNorm();
      if (e > error) error = e, worst = i;
    }
    return std::sqrt(error);
  }

  void reparameterise(const Cubic& c, int first, std::vector<double>& u) const {
    for (std::size_t k = 0; k < u.size(); ++k) {
      const Point2 d = c.at(u[k]) - p_[first + k];
      const Point2 q1 = c.d1(u[k]), q2 = c.d2(u[k]);
      const double denominator = q1.dot(q1) + d.dot(q2);
      if (std::abs(denominator) > 1e-12)
        u[k] = std::clamp(u[k] - d.dot(q1) / denominator, 0.0, 1.0);
    }
  }

  void fitRange(int first, int last, const Point2& t0, const Point2& t1, int depth) {
    if (last - first < 2 || depth > kMaxDepth || t0.isZero() || t1.isZero()) {
      for (int i = first; i < last; ++i) emitLine(i, i + 1);
      return;
    }
    std::vector<double> u = chordParameters(first, last);
    int worst = 0;
    Cubic cubic = generate(first, last, u, t0, t1);
    double error = maxError(cubic, first, last, u, worst);
    for (int k = 0; k < kNewtonIterations && error > tolerance_ && error < 4 * tolerance_; ++k) {
      reparameterise(cubic, first, u);
      cubic = generate(first, last, u, t0, t1);
      error = maxError(cubic, first, last, u, worst);
    }
    if (error <= tolerance_) return emit(cubic);
    const Point2 centre = unit(p_[worst - 1] - p_[worst + 1]);
    fitRange(first, worst, t0, centre, depth + 1);
    fitRange(worst, last, -centre, t1, depth + 1);
  }

  const std::vector<Point2>& p_;
  double tolerance_;
  std::vector<Point2>& out_;
  int segments_ = 0;
};

}  // namespace

int fitCubics(const std::vector<Point2>& points, const Point2& start_tangent,
              const Point2& end_tangent, double tolerance, std::vector<Point2>& control_points) {
  if (points.size() < 2) return 0;
  return Fitter(points, tolerance, control_points).fit(start_tangent, end_tangent);
}

}  // namespace io_detail
}  // namespace vicc_glyphs
