#include "kernel/complementarity/gauss_seidel.hpp"

#include <limits>

namespace heavesim {

GaussSeidelWorkspace::GaussSeidelWorkspace(int size)
    : minus_b(size),
      lower(VectorX::Constant(size, -std::numeric_limits<double>::infinity())),
      upper(VectorX::Constant(size, std::numeric_limits<double>::infinity())),
      sweep(size) {}

ComplementarityResult gauss_seidel(const MatrixX& A, const VectorX& b, GaussSeidelWorkspace& ws, VectorView x,
                                   const ProjectedGaussSeidelOptions& options) {
  if (b.size() != A.rows() || ws.minus_b.size() != b.size()) {
    ComplementarityResult result;
    result.solver = ComplementaritySolver::gauss_seidel;
    result.message = "Gauss-Seidel: b has " + std::to_string(b.size()) + " entries, A has " +
                     std::to_string(A.rows()) + " rows, the workspace is sized " + std::to_string(ws.minus_b.size()) +
                     " (all three must agree)";
    return result;
  }
  // A x = b is w = A x - b = 0 with x free: the box (-inf, +inf) makes the projection the
  // identity and the natural-map residual |A x - b|_inf.
  ws.minus_b = -b;
  const ComplementarityProblem problem{A, ws.minus_b, ws.lower, ws.upper};
  ComplementarityResult result = projected_gauss_seidel(problem, ws.sweep, x, options);
  result.solver = ComplementaritySolver::gauss_seidel;
  return result;
}

}  // namespace heavesim
