#include "direct_reference_solve.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vicc_glyphs {

std::vector<float> solveDirect(const GridProblem& problem) {
  const int n = problem.pixelCount();
  const int w = problem.width;
  std::vector<int> unknown(n, -1);
  int unknowns = 0;
  for (int p = 0; p < n; ++p) {
    if (!problem.fixed[p]) unknown[p] = unknowns++;
  }
  std::vector<float> result(problem.values);
  if (unknowns == 0) return result;

  // Row of free pixel p: degree * u_p - sum over coupled free q of u_q = sum of coupled
  // Dirichlet values. Symmetric positive definite because every free pixel is linked to a
  // Dirichlet pixel (grid_problem.hpp).
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(unknowns, problem.channels);
  for (int p = 0; p < n; ++p) {
    if (unknown[p] < 0) continue;
    const int x = p % w;
    const int row = unknown[p];
    double degree = 0.0;
    const auto link = [&](int q, bool coupled) {
      if (!coupled) return;
      degree += 1.0;
      if (unknown[q] >= 0) {
        entries.emplace_back(row, unknown[q], -1.0);
      } else {
        for (int c = 0; c < problem.channels; ++c) rhs(row, c) += problem.value(c, q);
      }
    };
    link(p + 1, problem.couples_right[p]);
    link(p + w, problem.couples_down[p]);
    link(p - 1, x > 0 && problem.couples_right[p - 1]);
    link(p - w, p >= w && problem.couples_down[p - w]);
    entries.emplace_back(row, row, degree);
  }
  Eigen::SparseMatrix<double> matrix(unknowns, unknowns);
  matrix.setFromTriplets(entries.begin(), entries.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(matrix);
  if (solver.info() != Eigen::Success)
    throw std::runtime_error("solveDirect: factorisation failed");
  const Eigen::MatrixXd solution = solver.solve(rhs);
  for (int p = 0; p < n; ++p) {
    if (unknown[p] < 0) continue;
    for (int c = 0; c < problem.channels; ++c) {
      result[static_cast<size_t>(p) * problem.channels + c] =
          static_cast<float>(solution(unknown[p], c));
    }
  }
  return result;
}

double meanAbsoluteError(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size()) throw std::invalid_argument("meanAbsoluteError: size mismatch");
  if (a.empty()) return 0.0;
  double sum = 0.0;
  for (size_t i = 0; i < a.size(); ++i) sum += std::abs(static_cast<double>(a[i]) - b[i]);
  return sum / static_cast<double>(a.size());
}

double maxAbsoluteError(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size()) throw std::invalid_argument("maxAbsoluteError: size mismatch");
  double worst = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    worst = std::max(worst, std::abs(static_cast<double>(a[i]) - b[i]));
  }
  return worst;
}

GridProblem openGridProblem(int width, int height, int channels) {
  GridProblem problem;
  problem.width = width;
  problem.height = height;
  problem.channels = channels;
  const size_t n = static_cast<size_t>(width) * height;
  problem.couples_right.assign(n, 1);
  problem.couples_down.assign(n, 1);
  problem.fixed.assign(n, 0);
  problem.values.assign(n * channels, 0.0f);
  for (int y = 0; y < height; ++y) problem.couples_right[y * width + width - 1] = 0;
  for (int x = 0; x < width; ++x) problem.couples_down[(height - 1) * width + x] = 0;
  return problem;
}

}  // namespace vicc_glyphs
