#include "kernel/complementarity/complementarity_problem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace heavesim {

namespace {
constexpr double infinity = std::numeric_limits<double>::infinity();

ComplementarityResult invalid(std::string message) {
  ComplementarityResult result;
  result.status = ComplementarityStatus::invalid_input;
  result.message = std::move(message);
  return result;
}

std::string entry(int i, int j) { return "(" + std::to_string(i) + ", " + std::to_string(j) + ")"; }
}  // namespace

double ComplementarityProblem::lower_bound(int i, const ConstVectorView& z) const {
  if (is_friction_row(i)) return -(*friction_coefficient)[i] * std::max(z[(*friction_normal)[i]], 0.0);
  return lower ? (*lower)[i] : 0.0;
}

double ComplementarityProblem::upper_bound(int i, const ConstVectorView& z) const {
  if (is_friction_row(i)) return (*friction_coefficient)[i] * std::max(z[(*friction_normal)[i]], 0.0);
  return upper ? (*upper)[i] : infinity;
}

const char* to_string(ComplementarityStatus status) {
  switch (status) {
    case ComplementarityStatus::solved: return "solved";
    case ComplementarityStatus::ray_termination: return "ray termination";
    case ComplementarityStatus::iteration_limit: return "pivot limit reached";
    case ComplementarityStatus::not_converged: return "not converged";
    case ComplementarityStatus::diverged: return "diverged";
    case ComplementarityStatus::singular_pivot: return "singular pivot";
    case ComplementarityStatus::unsupported: return "unsupported problem form";
    case ComplementarityStatus::invalid_input: return "invalid input";
  }
  return "?";
}

const char* to_string(ComplementaritySolver solver) {
  switch (solver) {
    case ComplementaritySolver::lemke: return "Lemke";
    case ComplementaritySolver::dantzig: return "Dantzig";
    case ComplementaritySolver::projected_gauss_seidel: return "projected Gauss-Seidel";
    case ComplementaritySolver::gauss_seidel: return "Gauss-Seidel";
  }
  return "?";
}

bool fits_workspace(ComplementarityResult& result, const char* solver, int capacity, int rows_needed, Eigen::Index z_size,
                    int n) {
  if (rows_needed <= capacity && z_size == n) return true;
  result.status = ComplementarityStatus::invalid_input;
  result.message = std::string(solver) + " workspace holds " + std::to_string(capacity) + " rows and z has " +
                   std::to_string(z_size) + " entries; the problem needs " + std::to_string(rows_needed) + " and " +
                   std::to_string(n);
  return false;
}

ComplementarityResult validate(const ComplementarityProblem& problem) {
  const ConstMatrixView& M = problem.M;
  const int n = problem.size();
  if (M.rows() != M.cols())
    return invalid("matrix M is " + std::to_string(M.rows()) + " x " + std::to_string(M.cols()) +
                   ", expected square");
  if (M.rows() != n)
    return invalid("vector q has " + std::to_string(n) + " entries, expected " + std::to_string(M.rows()) +
                   " (the size of M)");
  const auto check_size = [&](const auto& vector, const char* name) -> std::string {
    if (vector && vector->size() != n)
      return std::string(name) + " has " + std::to_string(vector->size()) + " entries, expected " +
             std::to_string(n);
    return {};
  };
  for (const std::string& error :
       {check_size(problem.lower, "lower bound lo"), check_size(problem.upper, "upper bound hi"),
        check_size(problem.friction_normal, "friction normal index"),
        check_size(problem.friction_coefficient, "friction coefficient mu")})
    if (!error.empty()) return invalid(error);
  if (problem.friction_normal.has_value() != problem.friction_coefficient.has_value())
    return invalid("friction rows need both the normal indices and the coefficients");
  if (!M.allFinite())  // vectorized; the entry is looked for only when there is one
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        if (!std::isfinite(M(i, j)))
          return invalid("matrix entry M" + entry(i, j) + " = " + std::to_string(M(i, j)) + ", expected finite");
  for (int i = 0; i < n; ++i) {
    if (!std::isfinite(problem.q[i]))
      return invalid("vector entry q(" + std::to_string(i) + ") = " + std::to_string(problem.q[i]) +
                     ", expected finite");
    const double lo = problem.lower ? (*problem.lower)[i] : 0.0;
    const double hi = problem.upper ? (*problem.upper)[i] : infinity;
    if (std::isnan(lo) || std::isnan(hi) || lo > hi || lo == infinity || hi == -infinity)
      return invalid("row " + std::to_string(i) + ": bounds [" + std::to_string(lo) + ", " + std::to_string(hi) +
                     "], expected lo <= hi, neither NaN");
    if (problem.is_friction_row(i)) {
      const int normal = (*problem.friction_normal)[i];
      const double mu = (*problem.friction_coefficient)[i];
      if (normal >= n || normal == i)
        return invalid("friction row " + std::to_string(i) + ": normal index " + std::to_string(normal) +
                       ", expected another row in [0, " + std::to_string(n) + ")");
      if (problem.is_friction_row(normal))
        return invalid("friction row " + std::to_string(i) + ": normal row " + std::to_string(normal) +
                       " is itself a friction row");
      if (!(mu >= 0.0) || !std::isfinite(mu))
        return invalid("friction row " + std::to_string(i) + ": coefficient mu = " + std::to_string(mu) +
                       ", expected finite and >= 0");
    }
  }
  ComplementarityResult result;
  result.status = ComplementarityStatus::solved;
  return result;
}

void evaluate_residual(const ComplementarityProblem& problem, const ConstVectorView& z, VectorView w,
                       ComplementarityResult& result) {
  w.noalias() = problem.M * z;
  w += problem.q;
  double largest = 0.0;
  for (int i = 0; i < problem.size(); ++i) {
    const double projected = std::clamp(z[i] - w[i], problem.lower_bound(i, z), problem.upper_bound(i, z));
    const double r = std::abs(z[i] - projected);
    largest = std::isnan(r) ? infinity : std::max(largest, r);
  }
  const double scale = problem.q.size() ? problem.q.lpNorm<Eigen::Infinity>() : 0.0;
  result.residual_absolute = largest;
  result.residual = largest / (scale > 0.0 ? scale : 1.0);
}

}  // namespace heavesim
