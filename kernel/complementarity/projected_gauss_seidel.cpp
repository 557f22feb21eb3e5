#include "kernel/complementarity/projected_gauss_seidel.hpp"

#include <algorithm>
#include <cmath>

namespace heavesim {

ProjectedGaussSeidelWorkspace::ProjectedGaussSeidelWorkspace(int size)
    : capacity(size), transposed(size, size), w(size) {}

ComplementarityResult projected_gauss_seidel(const ComplementarityProblem& problem,
                                             ProjectedGaussSeidelWorkspace& ws, VectorView z,
                                             const ProjectedGaussSeidelOptions& options) {
  ComplementarityResult result = validate(problem);
  result.solver = ComplementaritySolver::projected_gauss_seidel;
  if (!result.solved()) return result;
  const int n = problem.size();
  if (!fits_workspace(result, "projected Gauss-Seidel", ws.capacity, n, z.size(), n)) return result;
  if (!(options.relaxation > 0.0 && options.relaxation < 2.0)) {
    result.status = ComplementarityStatus::invalid_input;
    result.message = "projected Gauss-Seidel: relaxation " + std::to_string(options.relaxation) + ": expected in (0, 2)";
    return result;
  }
  for (int i = 0; i < n; ++i)
    if (!(problem.M(i, i) > 0.0)) {
      result.status = ComplementarityStatus::singular_pivot;
      result.message = "projected Gauss-Seidel needs M_ii > 0; M(" + std::to_string(i) + ", " + std::to_string(i) +
                       ") = " + std::to_string(problem.M(i, i));
      return result;
    }
  auto Mt = ws.transposed.topLeftCorner(n, n);
  Mt = problem.M.transpose();
  if (!options.warm_start) z.setZero();
  for (int i = 0; i < n; ++i) z[i] = std::clamp(z[i], problem.lower_bound(i, z), problem.upper_bound(i, z));
  result.pivot_limit = options.max_iterations;
  evaluate_residual(problem, z, ws.w.head(n), result);
  const double start = result.residual_absolute;
  for (result.iterations = 0; result.iterations < options.max_iterations;) {
    if (result.residual <= options.tolerance) {
      result.status = ComplementarityStatus::solved;
      return result;
    }
    for (int i = 0; i < n; ++i) {
      const double w_i = Mt.col(i).dot(z) + problem.q[i];
      z[i] = std::clamp(z[i] - options.relaxation * w_i / problem.M(i, i), problem.lower_bound(i, z),
                        problem.upper_bound(i, z));
    }
    ++result.iterations;
    evaluate_residual(problem, z, ws.w.head(n), result);
    if (!std::isfinite(result.residual_absolute) || result.residual_absolute > 1e12 * std::max(start, 1e-300)) {
      result.status = ComplementarityStatus::diverged;
      result.message = "projected Gauss-Seidel diverged after " + std::to_string(result.iterations) +
                       " sweeps (residual " + std::to_string(result.residual_absolute) +
                       "): M is not positive definite or the relaxation is too large";
      return result;
    }
  }
  if (result.residual <= options.tolerance) {
    result.status = ComplementarityStatus::solved;
    return result;
  }
  result.status = ComplementarityStatus::not_converged;
  result.message = "projected Gauss-Seidel: relative residual " + std::to_string(result.residual) + " after " +
                   std::to_string(result.iterations) + " sweeps";
  return result;
}

}  // namespace heavesim
