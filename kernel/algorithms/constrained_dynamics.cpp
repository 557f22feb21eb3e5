#include "kernel/algorithms/constrained_dynamics.hpp"

#include "kernel/algorithms/constraint_equations.hpp"

namespace heavesim {

const VectorX& constrained_forward_dynamics(const Model& model, Data& data, double t, const VectorX& tau,
                                            ExternalForces external_forces_world) {
  // Unconstrained accelerations; keeps M's Cholesky factor in data.
  data.kkt_free_qdd = composite_rigid_body_forward_dynamics(model, data, tau, external_forces_world);
  if (!model.has_constraints()) return data.qdd;

  constraint_jacobian(model, data, t, data.constraint_jacobian);
  constraint_bias(model, data, t, data.constraint_bias);
  if (data.constraint_rows_set_aside) {
    // Rows set aside as redundant take no part: zero rows of J and gamma give zero rows
    // and columns of J M^-1 J^T, whose regularized solve returns lambda = 0 there.
    data.constraint_jacobian.array().colwise() *= data.constraint_row_used.array();
    data.constraint_bias.array() *= data.constraint_row_used.array();
  }

  // Y = M^-1 J^T, A = J Y, b = gamma - J qdd_free.
  data.kkt_minv_jt = data.constraint_jacobian.transpose();
  data.mass_matrix_cholesky.solveInPlace(data.kkt_minv_jt);
  data.kkt_schur.noalias() = data.constraint_jacobian * data.kkt_minv_jt;
  data.kkt_rhs = data.constraint_bias;
  data.kkt_rhs.noalias() -= data.constraint_jacobian * data.kkt_free_qdd;

  data.kkt_solver.compute(data.kkt_schur, kkt_regularization);
  data.kkt_solver.solve(data.kkt_rhs, data.constraint_multipliers);
  data.qdd = data.kkt_free_qdd;
  data.qdd.noalias() += data.kkt_minv_jt * data.constraint_multipliers;
  data.stages.accelerations_computed();  // (the unconstrained path set it already)
  return data.qdd;
}

}  // namespace heavesim
