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

}  // namespace vicc_glyphs
