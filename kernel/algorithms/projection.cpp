#include "kernel/algorithms/projection.hpp"

#include <algorithm>

#include <Eigen/QR>

#include "kernel/algorithms/configuration.hpp"
#include "kernel/algorithms/constrained_dynamics.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "kernel/algorithms/mass_matrix.hpp"
#include "kernel/algorithms/constraint_equations.hpp"

namespace heavesim {
namespace {

/// step = -M^-1 J^T (J M^-1 J^T)^+ r for the current J and M's Cholesky factor.
void minimum_energy_correction(Data& data, const VectorX& r) {
  data.kkt_minv_jt = data.constraint_jacobian.transpose();
  data.mass_matrix_cholesky.solveInPlace(data.kkt_minv_jt);
  data.kkt_schur.noalias() = data.constraint_jacobian * data.kkt_minv_jt;
  data.kkt_solver.compute(data.kkt_schur, kkt_regularization);
  data.kkt_solver.solve(r, data.kkt_rhs);
  data.projection_step.noalias() = -data.kkt_minv_jt * data.kkt_rhs;
}

}  // namespace

ProjectionResult project_to_constraints(const Model& model, Data& data, double t, VectorX& q, VectorX& v,
                                        double tolerance, int max_iterations) {
  ProjectionResult result;
  if (!model.has_constraints()) {
    result.converged = true;
    return result;
  }
  for (;;) {
    update_positions(model, data, q);
    constraint_residual(model, data, q, t, data.constraint_residual);
    result.position_residual = data.constraint_residual.cwiseAbs().maxCoeff();
    if (result.position_residual <= tolerance || result.iterations >= max_iterations) break;
    constraint_jacobian(model, data, t, data.constraint_jacobian);
    factorize_mass_matrix(model, data);
    minimum_energy_correction(data, data.constraint_residual);
    data.projection_configuration = q;
    integrate_configuration(model, data.projection_configuration, data.projection_step, 1.0, q);
    ++result.iterations;
  }
  result.converged = result.position_residual <= tolerance;

  // Velocities: v -= M^-1 J^T (J M^-1 J^T)^+ (J v - nu) at the projected configuration.
  constraint_jacobian(model, data, t, data.constraint_jacobian);
  constraint_velocity_target(model, data, t, data.constraint_velocity_target);
  factorize_mass_matrix(model, data);
  data.constraint_bias.noalias() = data.constraint_jacobian * v;  // workspace: J v - nu
  data.constraint_bias -= data.constraint_velocity_target;
  minimum_energy_correction(data, data.constraint_bias);
  v += data.projection_step;
  data.constraint_bias.noalias() = data.constraint_jacobian * v;
  data.constraint_bias -= data.constraint_velocity_target;
  result.velocity_residual = data.constraint_bias.cwiseAbs().maxCoeff();
  return result;
}

ConstraintRank analyse_constraint_rank(const Model& model, Data& data, double t, double relative_threshold) {
  ConstraintRank result;
  result.rows = model.num_constraint_rows;
  if (result.rows == 0) return result;
  constraint_jacobian(model, data, t, data.constraint_jacobian);
  Eigen::ColPivHouseholderQR<MatrixX> qr(data.constraint_jacobian.transpose());
  qr.setThreshold(relative_threshold);
  result.rank = static_cast<int>(qr.rank());
  // Pivoting brings independent rows (columns of J^T) first; the rest depend on them. An
  // inactive row (zero) is among the rest, but it is not redundant: it is not there.
  for (int k = result.rank; k < result.rows; ++k) {
    const int row = qr.colsPermutation().indices()[k];
    (data.constraint_active[row] != 0.0 ? result.redundant_rows : result.inactive_rows).push_back(row);
  }
  std::sort(result.redundant_rows.begin(), result.redundant_rows.end());
  std::sort(result.inactive_rows.begin(), result.inactive_rows.end());
  return result;
}

std::vector<int> ConstraintRank::independent_rows() const {
  std::vector<int> kept;
  for (int row = 0; row < rows; ++row)
    if (!std::binary_search(redundant_rows.begin(), redundant_rows.end(), row) &&
        !std::binary_search(inactive_rows.begin(), inactive_rows.end(), row))
      kept.push_back(row);
  return kept;
}

const Constraint* constraint_of_row(const Model& model, int row) {
  for (const Constraint& constraint : model.constraints)
    if (row >= constraint.first_row && row < constraint.first_row + static_cast<int>(constraint.rows.size()))
      return &constraint;
  return nullptr;
}

std::string describe_constraint_row(const Model& model, int row) {
  const Constraint* constraint = constraint_of_row(model, row);
  if (!constraint) return "row " + std::to_string(row);
  return std::string(constraint->kind_name()) + " '" + constraint->name + "': " + constraint->rows[row - constraint->first_row].description;
}

}  // namespace heavesim
