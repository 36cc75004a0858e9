#pragma once
// Reference for the multigrid: a direct sparse solve (Eigen SimplicialLDLT) of exactly the
// GridProblem the renderer assembles.

#include <vector>

#include "vicc_glyphs/render/grid_problem.hpp"

namespace vicc_glyphs {

/// Solves `problem` directly; returns width*height*channels values, pixel-major like
/// GridProblem::values (Dirichlet pixels keep their values). Throws std::runtime_error if the
/// factorisation fails.
std::vector<float> solveDirect(const GridProblem& problem);

/// Mean absolute difference of two equally sized value arrays.
double meanAbsoluteError(const std::vector<float>& a, const std::vector<float>& b);
/// Largest absolute difference of two equally sized value arrays.
double maxAbsoluteError(const std::vector<float>& a, const std::vector<float>& b);

/// A width x height problem with every link inside the grid kept (Neumann borders), no
/// Dirichlet pixel and all values 0: the tests cut links and fix pixels in it.
GridProblem openGridProblem(int width, int height, int channels);

}  // namespace vicc_glyphs
