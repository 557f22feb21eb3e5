#include "kernel/analysis/kinematic_analysis.hpp"

#include <algorithm>
#include <cmath>

#include "kernel/algorithms/configuration.hpp"
#include "kernel/algorithms/constraint_equations.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "kernel/algorithms/mass_matrix.hpp"
#include "kernel/algorithms/projection.hpp"

namespace heavesim {
namespace {

/// J at the current position stage and its minimum-norm factorization in the metric; for
/// the mass metric, M's Cholesky factor is taken at this stage when `update_metric` (else
/// the one in data is kept: in the Newton iterations the metric only chooses among the
/// solutions of J dq = -Phi, and the factor of the last solved point, O(h) away, serves).
void factorize_constraints(const Model& model, Data& data, KinematicWorkspace& workspace,
                           const KinematicSettings& settings, double t, bool update_metric) {
  constraint_jacobian(model, data, t, data.constraint_jacobian);
  const Eigen::LLT<MatrixX>* metric = nullptr;
  if (settings.weighting == MotionWeighting::mass) {
    if (update_metric) factorize_mass_matrix(model, data);
    metric = &data.mass_matrix_cholesky;
  }
  workspace.solver.factorize(data.constraint_jacobian, metric, kinematic_rank_threshold);
}

/// max |Phi(q, t)| after the position stage at q (leaves Phi in data).
double equation_error(const Model& model, Data& data, const VectorX& q, double t) {
  update_positions(model, data, q);
  constraint_residual(model, data, q, t, data.constraint_residual);
  return data.constraint_residual.size() > 0 ? data.constraint_residual.cwiseAbs().maxCoeff() : 0.0;
}

}  // namespace

KinematicWorkspace::KinematicWorkspace(const Model& model)
    : solver(model.nv, model.num_constraint_rows),
      triangle(MatrixX::Zero(std::min(model.nv, model.num_constraint_rows), model.num_constraint_rows)),
      svd(static_cast<int>(triangle.rows()), model.num_constraint_rows),
      step(VectorX::Zero(model.nv)),
      trial(VectorX::Zero(model.nq)),
      rhs(VectorX::Zero(model.num_constraint_rows)),
      predicted(VectorX::Zero(model.nv)) {}

KinematicPoint solve_positions(const Model& model, Data& data, KinematicWorkspace& workspace,
                               const KinematicSettings& settings, double t, VectorX& q) {
  KinematicPoint point;
  double error = equation_error(model, data, q, t);
  // MKSim's two tests: the equations hold (max |Phi|) and the iterate has stopped moving
  // (max |dq| of the last step). Before any step the second is unknown, so at least one
  // step is taken unless Phi is exactly zero.
  bool stepped = false;
  while (true) {
    if (error <= settings.equation_tolerance &&
        (error == 0.0 || (stepped && point.last_step <= settings.solution_tolerance))) {
      point.converged = true;
      break;
    }
    if (point.newton_iterations >= settings.max_iterations) break;
    factorize_constraints(model, data, workspace, settings, t, !workspace.metric_held);
    workspace.metric_held = true;
    workspace.rhs = -data.constraint_residual;
    workspace.solver.solve(workspace.rhs, workspace.step);  // J dq = -Phi, minimum-norm in W
    const double full_norm = data.constraint_residual.norm();
    // Backtracking (Armijo) on |Phi|_2: Newton's direction decreases it at rate 1 for a
    // consistent system; halve the step until it does (Dennis & Schnabel 1983, 6.3). Once
    // the equations hold, the step only refines the solution: take it whole.
    double alpha = 1.0, trial_error = 0.0;
    for (;;) {
      integrate_configuration(model, q, workspace.step, alpha, workspace.trial);
      trial_error = equation_error(model, data, workspace.trial, t);
      if (error <= settings.equation_tolerance || alpha < 1.0 / 64.0 ||
          data.constraint_residual.norm() <= (1.0 - 1e-4 * alpha) * full_norm)
        break;
      alpha *= 0.5;
    }
    q.swap(workspace.trial);  // (integrate_configuration keeps quaternions unit)
    error = trial_error;
    point.last_step = alpha * workspace.step.cwiseAbs().maxCoeff();
    stepped = true;
    ++point.newton_iterations;
  }
  // The position stage and Phi are at the returned q (its evaluation was the last one);
  // J and its factorization follow.
  point.equation_residual = error;
  if (model.has_constraints()) {
    // The velocity and acceleration solves need the exact metric at q.
    factorize_constraints(model, data, workspace, settings, t, true);
    point.rank = workspace.solver.rank();
    if (workspace.reference_rank < 0) workspace.reference_rank = point.rank;
    // sigma_rank / sigma_max of the weighted Jacobian A = J L^-T: the singular values of
    // the QR's R factor (square when nv >= m), so that the SVD needs no QR of its own.
    workspace.solver.triangular_factor(workspace.triangle);
    workspace.svd.compute(workspace.triangle);
    const VectorX& sigma = workspace.svd.singularValues();
    const int k = workspace.reference_rank - 1;
    point.singular_ratio = (k >= 0 && k < sigma.size() && sigma[0] > 0.0) ? sigma[k] / sigma[0] : 1.0;
  }
  return point;
}

void solve_velocities_and_accelerations(const Model& model, Data& data, KinematicWorkspace& workspace, double t,
                                        const VectorX& q, VectorX& v, VectorX& a) {
  if (!model.has_constraints()) {
    v.setZero();
    update_velocities(model, data, q, v);
    a.setZero();
    return;
  }
  constraint_velocity_target(model, data, t, data.constraint_velocity_target);
  workspace.solver.solve(data.constraint_velocity_target, v);
  update_velocities(model, data, q, v);
  constraint_bias(model, data, t, data.constraint_bias);
  workspace.solver.solve(data.constraint_bias, a);
}

KinematicPoint analyse_time_point(const Model& model, Data& data, KinematicWorkspace& workspace,
                                  const KinematicSettings& settings, double t, double h, VectorX& q, VectorX& v,
                                  VectorX& a) {
  if (h != 0.0) {
    // Second-order Taylor prediction on the manifold: an error of O(h^3), far inside the
    // basin of the branch the motion is on.
    workspace.predicted = h * v;
    workspace.predicted.noalias() += (0.5 * h * h) * a;
    integrate_configuration(model, q, workspace.predicted, 1.0, workspace.trial);
    q.swap(workspace.trial);
  }
  const KinematicPoint point = solve_positions(model, data, workspace, settings, t, q);
  if (point.converged) solve_velocities_and_accelerations(model, data, workspace, t, q, v, a);
  return point;
}

std::vector<InconsistentRows> inconsistent_rows(const Model& model, Data& data, double t, double tolerance) {
  std::vector<InconsistentRows> found;
  const ConstraintRank rank = analyse_constraint_rank(model, data, t);  // leaves J in data
  if (rank.redundant_rows.empty()) return found;
  const std::vector<int> independent = rank.independent_rows();
  MatrixX basis(model.nv, static_cast<int>(independent.size()));
  VectorX phi_independent(basis.cols());
  for (int k = 0; k < basis.cols(); ++k) {
    basis.col(k) = data.constraint_jacobian.row(independent[k]).transpose();
    phi_independent[k] = data.constraint_residual[independent[k]];
  }
  Eigen::ColPivHouseholderQR<MatrixX> qr(basis.rows(), basis.cols());
  if (basis.cols() > 0) qr.compute(basis);
  for (const int row : rank.redundant_rows) {
    // J_row^T = basis c (exactly, up to the rank threshold): c by least squares; a zero
    // row (rank 0) depends on nothing.
    const VectorX c = basis.cols() > 0 ? VectorX(qr.solve(VectorX(data.constraint_jacobian.row(row).transpose())))
                                       : VectorX();
    const double mismatch = data.constraint_residual[row] - c.dot(phi_independent);
    if (!(std::abs(mismatch) > tolerance)) continue;
    InconsistentRows rows{row, {}, mismatch};
    const double largest = c.size() > 0 ? c.cwiseAbs().maxCoeff() : 0.0;
    for (int k = 0; k < c.size(); ++k)
      if (std::abs(c[k]) > 1e-8 * largest) rows.rows.push_back(independent[k]);
    found.push_back(std::move(rows));
  }
  return found;
}

}  // namespace heavesim
