#include "kernel/complementarity/fallback_chain.hpp"

#include <cmath>
#include <cstdio>

namespace heavesim {

namespace {

std::string format_residual(double residual) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", residual);
  return text;
}

}  // namespace

ComplementarityResult solve_complementarity(const ComplementarityProblem& problem, ComplementarityWorkspace& ws,
                                            VectorView z, const FallbackChainOptions& options) {
  ComplementarityResult result = validate(problem);
  if (!result.solved()) return result;
  std::string failures;
  for (int k = 0; k < options.count; ++k) {
    switch (options.order[k]) {
      case ComplementaritySolver::lemke: result = lemke(problem, ws.lemke, z, options.lemke); break;
      case ComplementaritySolver::dantzig: result = dantzig(problem, ws.dantzig, z, options.dantzig); break;
      case ComplementaritySolver::projected_gauss_seidel:
      case ComplementaritySolver::gauss_seidel:
        result = projected_gauss_seidel(problem, ws.projected_gauss_seidel, z, options.projected_gauss_seidel);
        break;
    }
    result.attempts = k + 1;
    if (result.solved() || result.status == ComplementarityStatus::invalid_input) {
      if (!failures.empty()) result.message = "after " + failures;  // which solvers failed before
      return result;
    }
    failures += std::string(failures.empty() ? "" : "; ") + to_string(result.solver) + ": " +
                to_string(result.status);
    // The residual its answer left, where it produced one (a caller reports the closest).
    if (result.status != ComplementarityStatus::unsupported && std::isfinite(result.residual))
      failures += ", residual " + format_residual(result.residual);
  }
  result.message = "no solver of the chain solved the problem (" + failures + "); last: " + result.message;
  return result;
}

}  // namespace heavesim
