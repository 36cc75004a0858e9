#include "vicc_glyphs/bspline/curve_energy.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace vicc_glyphs {
namespace bspline {
namespace {

// Gauss-Legendre nodes and weights on [-1, 1] by the Golub-Welsch eigenvalue method: exact for
// polynomials up to degree 2 * count - 1.
std::pair<Eigen::VectorXd, Eigen::VectorXd> gaussLegendre(int count) {
  Eigen::MatrixXd jacobi = Eigen::MatrixXd::Zero(count, count);
  for (int i = 1; i < count; ++i) {
    const double b = i / std::sqrt(4.0 * i * i - 1.0);
    jacobi(i, i - 1) = b;
    jacobi(i - 1, i) = b;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(jacobi);
  const Eigen::VectorXd weights = 2.0 * solver.eigenvectors().row(0).transpose().array().square();
  return {solver.eigenvalues(), weights};
}

void checkOrder(const BSplineCurve& curve, int order) {
  if (order < 1 || order > curve.degree()) {
    throw std::invalid_argument("curve energy: derivative order must be in [1, degree]");
  }
}

// Calls visit(u, weight) for the quadrature points of every knot span; products of two
// derivatives of order `order` have degree 2 (p - order), so p + 1 - order nodes are exact.
template <typename Visit>
void forEachQuadraturePoint(const BSplineCurve& curve, int order, Visit visit) {
  const auto [nodes, weights] = gaussLegendre(curve.degree() + 1 - order);
  const std::vector<double> breaks = curve.breakpoints();
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
    const double half = 0.5 * (breaks[k + 1] - breaks[k]);
    const double mid = 0.5 * (breaks[k + 1] + breaks[k]);
    for (int q = 0; q < nodes.size(); ++q) visit(mid + half * nodes[q], half * weights[q]);
  }
}

}  // namespace

Eigen::SparseMatrix<double> energyMatrix(const BSplineCurve& basis, int order) {
  checkOrder(basis, order);
  std::vector<Eigen::Triplet<double>> entries;
  forEachQuadraturePoint(basis, order, [&](double u, double weight) {
    const BasisRow row = basis.basisAt(u, order);
    for (int a = 0; a < row.values.size(); ++a) {
      for (int b = 0; b < row.values.size(); ++b) {
        entries.emplace_back(row.first_index + a, row.first_index + b,
                             weight * row.values[a] * row.values[b]);
      }
    }
  });
  const int n = basis.controlPointCount();
  Eigen::SparseMatrix<double> gram(n, n);
  gram.setFromTriplets(entries.begin(), entries.end());  // sums duplicate entries
  return gram;
}

double curveEnergy(const BSplineCurve& curve, int order) {
  checkOrder(curve, order);
  double energy = 0.0;
  forEachQuadraturePoint(curve, order, [&](double u, double weight) {
    energy += weight * curve.derivativeAt(u, order).squaredNorm();
  });
  return energy;
}

}  // namespace bspline
}  // namespace vicc_glyphs
