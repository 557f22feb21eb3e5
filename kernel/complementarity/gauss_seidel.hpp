#pragma once
// Plain Gauss-Seidel for a linear system A x = b (Golub & Van Loan 2013, 11.2):
//   x_i <- (b_i - sum_{j != i} A_ij x_j) / A_ii, row by row with the newest values.
// It converges for strictly diagonally dominant A and for symmetric positive definite A;
// otherwise it may diverge, which is reported (status diverged), never returned as an
// answer. It is the projected iteration with every box (-inf, +inf): one sweep, two uses.
#include "kernel/complementarity/projected_gauss_seidel.hpp"

namespace heavesim {

/// Buffers for systems of up to `size` rows, sized once.
struct GaussSeidelWorkspace {
  explicit GaussSeidelWorkspace(int size = 0);
  VectorX minus_b, lower, upper;
  ProjectedGaussSeidelWorkspace sweep;
};

/// x: the start (used as is when options.warm_start, else 0) and the answer. The residual
/// reported is |A x - b|_inf (/ |b|_inf for the relative one).
ComplementarityResult gauss_seidel(const MatrixX& A, const VectorX& b, GaussSeidelWorkspace& workspace, VectorView x,
                                   const ProjectedGaussSeidelOptions& options = {});

}  // namespace heavesim
