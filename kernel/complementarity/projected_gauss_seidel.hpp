#pragma once
// Projected Gauss-Seidel / successive over-relaxation for the boxed MLCP with friction
// coupling (Cryer 1971; Erleben 2013; Catto's sequential impulses are the same iteration
// written on body velocities): row by row,
//   z_i <- mid(lo_i, hi_i, z_i - omega (M_i z + q_i) / M_ii),
// with a friction row's box taken from the current value of its normal row. It converges
// for symmetric positive definite M and 0 < omega < 2, only linearly, at a rate that
// degrades with the condition of M (mass ratios, long stacks); it needs M_ii > 0.
#include "kernel/complementarity/complementarity_problem.hpp"

namespace heavesim {

struct ProjectedGaussSeidelOptions {
  double relaxation = 1.0;  ///< omega in (0, 2); 1: Gauss-Seidel
  int max_iterations = 1000;  ///< sweeps
  double tolerance = 1e-10;   ///< on the relative natural-map residual, checked after every sweep
  bool warm_start = false;    ///< start from the z passed in (projected on the box) instead of 0
};

/// Buffers for problems of up to `size` rows, sized once.
struct ProjectedGaussSeidelWorkspace {
  explicit ProjectedGaussSeidelWorkspace(int size = 0);
  int capacity = 0;
  MatrixX transposed;  ///< M^T: row i of M as a contiguous column
  VectorX w;
};

ComplementarityResult projected_gauss_seidel(const ComplementarityProblem& problem,
                                             ProjectedGaussSeidelWorkspace& workspace, VectorView z,
                                             const ProjectedGaussSeidelOptions& options = {});

}  // namespace heavesim
