// The stabilized index-2 form of a multibody model for IDA (Gear, Gupta & Leimkuhler
// 1985; the form of SUNDIALS' idaSlCrank example), y = [q; v; z; lambda; mu]:
//   F_q  = q' - N(q) (v - J^T mu)         mu keeps q on Phi = 0 (mu = 0 at the solution)
//   F_v  = ID(q, v, v') - tau - J^T lambda  one RNEA pass: no forward dynamics
//   F_z  = z' - g(t, q, v, z)
//   F_lambda = J v - nu(t)                  velocity-level constraints (nu = -dPhi/dt: drivers)
//   F_mu = Phi(q, t)                        position-level constraints
// lambda and mu are algebraic (excluded from IDA's error test).
//
// Redundant constraint rows (a planar loop closed by a 3-D revolute joint, two
// parallel rods on one block) would make the Newton matrix singular: the DAE keeps
// only the independent rows found by the rank-revealing QR at the initial state
// (analyse_constraint_rank), as multibody codes do; the others then hold by
// themselves. Reported multipliers still come from evaluate(), the minimum-norm
// solution over all rows.
//
// The Newton matrix's parts dF/dy and dF/dy' are assembled from the dynamics' partial
// derivatives (dynamics_differentiator.hpp: analytic M, dID/dq, dID/dv; differences for
// the elements and the q-dependence of J^T lambda, J^T mu and J v), J, Phi_q = J N+
// and N. Derivatives in q are taken along tangent directions and mapped to the raw
// coordinates with N+ (unit quaternions: 4 N^T).
#include "kernel/system/ggl_dae_form.hpp"

#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/QR>

#include "kernel/algorithms/configuration.hpp"
#include "kernel/algorithms/constraint_equations.hpp"
#include "kernel/algorithms/inverse_dynamics.hpp"
#include "kernel/algorithms/mass_matrix.hpp"
#include "kernel/algorithms/projection.hpp"
#include "kernel/math/index_list.hpp"

namespace heavesim {

GglDaeForm::GglDaeForm(MultibodySystem& system)
    : system_(system), differentiator_(system), stop_events_(system) {}

void GglDaeForm::event_values(double t, const VectorX& y, Eigen::Ref<VectorX> g) {
  // An active stop's force from the dynamics at (t, y), not the DAE's lambda: IDA
  // interpolates the multipliers for its root search, and they take no part in its error
  // test, so their interpolant may cross zero where the force does not (a stop let go
  // while it was still pressed, then passed). One evaluation, only while a stop is active.
  bool any_active = false;
  for (int e = 0; e < stop_events_.count(); ++e) any_active |= stop_events_.active(e);
  const int size = system_.size();
  if (any_active) {
    ode_rate_.resize(size);
    system_.state_derivative(t, y.head(size), ode_rate_);
  }
  const VectorX& lambda = system_.data().constraint_multipliers;
  stop_events_.values(y.head(system_.model().nq), [&](int row) { return lambda[row]; }, g);
}

bool GglDaeForm::handle_events(double t, const VectorX&, const std::vector<int>& found, VectorX& state) {
  stop_events_.handle(t, state, found);
  // The state IDA interpolated at the event holds the velocity constraints only to its
  // tolerance (1e-11 m/s here). A restart from it would have the first step take up that
  // mismatch as a velocity jump of the same size whatever the step -- which a speed with
  // a weight of 1 / atol cannot pass (the error test failed down to h = 1e-16 s, at rtol
  // 1e-10). So the state goes back onto Phi = 0, J v = nu with the new active set first.
  const Model& model = system_.model();
  VectorX q = state.head(model.nq), v = state.segment(model.nq, model.nv);
  project_to_constraints(model, system_.mutable_data(), t, q, v, system_.settings().projection_tolerance,
                         system_.settings().projection_iterations);
  state.head(model.nq) = q;
  state.segment(model.nq, model.nv) = v;
  return true;
}

void GglDaeForm::differential_mask(VectorX& mask) const {
  mask.setZero(dae_size());
  mask.head(system_.size()).setOnes();
}

void GglDaeForm::dae_initial_values(double t, const VectorX& state, VectorX& y, VectorX& yp) {
  const Model& model = system_.model();
  Data& data = system_.mutable_data();
  const int size = system_.size();
  ode_rate_.resize(size);
  system_.state_derivative(t, state, ode_rate_);  // qdd and, with loops, lambda from the KKT solve
  rows_.clear();
  if (model.has_constraints()) {
    // The ODE evaluation left the position stage at q and lambda of all rows.
    const ConstraintRank rank = analyse_constraint_rank(model, data, t);
    rows_ = rank.independent_rows();
    system_.remember_constraint_rank(rank.rank);
  }
  const int kept = kept_rows();
  // Each equation divided by a constant of its own units, so that the Newton matrix's
  // rows are all of the coordinates' units (rad/s or m/s, rad/s^2, rad): F_v by M_ii,
  // F_lambda and F_mu by |J_i|. Newton's updates do not change (a row scaling), but the
  // LU's pivoting and round-off no longer depend on the units the case is written in
  // (measured on Andrews' mechanism, IDA at rtol = atol = 1e-10: error 7.5e-8 rad in SI
  // against 3.8e-9 in mm-g-s before, the torque rows being 1e-5 of the others in SI).
  const VectorX mass_diagonal = mass_matrix(model, data).diagonal();
  equation_scale_.setOnes(dae_size());
  for (int k = 0; k < model.nv; ++k)
    if (mass_diagonal[k] > 0.0) equation_scale_[model.nq + k] = 1.0 / mass_diagonal[k];
  y.setZero(dae_size());
  yp.setZero(dae_size());
  y.head(size) = state;
  yp.head(size) = ode_rate_;
  rows_jacobian_.resize(kept, model.nv);
  rows_jacobian_in_newton_matrix_.resize(kept, model.nv);
  constraint_.resize(kept);
  if (kept == 0) return;
  // Multipliers of the kept rows giving the same constraint force J^T lambda (mu = 0).
  const MatrixX J_kept = data.constraint_jacobian(index_list(rows_), Eigen::all);
  // How an error in mu moves its constraint over a step h: the BDF corrector turns a
  // d(mu) into a position error h N J^T d(mu), so Phi_i by h (J J^T)_ii d(mu_i)
  // (N+ N = I).
  position_row_scale_ = J_kept.rowwise().squaredNorm();
  for (int k = 0; k < kept; ++k) {
    const double row_norm = std::sqrt(position_row_scale_[k]);
    if (row_norm > 0.0) equation_scale_[size + k] = equation_scale_[size + kept + k] = 1.0 / row_norm;
  }
  const VectorX generalized_force = data.constraint_jacobian.transpose() * data.constraint_multipliers;
  y.segment(size, kept) = J_kept.transpose().colPivHouseholderQr().solve(generalized_force);
}

void GglDaeForm::residual(double t, const VectorX& y, const VectorX& yp, VectorX& r) {
  const Model& model = system_.model();
  Data& data = system_.mutable_data();
  const int nq = model.nq, nv = model.nv, size = system_.size(), nz = size - nq - nv, m = kept_rows();
  vdot_ = yp.segment(nq, nv);
  system_.compute_stages_and_forces(t, y);
  const VectorX& q = system_.configuration();
  const VectorX& v = system_.velocity();
  const AppliedForces& forces = system_.applied_forces();
  r.segment(nq, nv) = inverse_dynamics(model, data, vdot_, forces.external_force_world);
  r.segment(nq, nv) -= forces.joint_force;
  w_ = v;
  if (m > 0) {
    constraint_jacobian(model, data, t, data.constraint_jacobian);
    constraint_residual(model, data, q, t, data.constraint_residual);
    constraint_velocity_target(model, data, t, data.constraint_velocity_target);
    rows_jacobian_ = data.constraint_jacobian(index_list(rows_), Eigen::all);
    constraint_ = data.constraint_residual(index_list(rows_));
    r.segment(nq, nv).noalias() -= rows_jacobian_.transpose() * y.segment(size, m);
    w_.noalias() -= rows_jacobian_.transpose() * y.segment(size + m, m);
    r.segment(size, m).noalias() = rows_jacobian_ * v;
    r.segment(size, m) -= data.constraint_velocity_target(index_list(rows_));
    r.segment(size + m, m) = constraint_;
  }
  qdot_.resize(nq);
  configuration_derivative(model, q, w_, qdot_);
  r.head(nq) = yp.head(nq) - qdot_;
  if (nz > 0) {
    zdot_.resize(nz);
    system_.element_state_derivatives(t, y, data, zdot_);
    r.segment(nq + nv, nz) = yp.segment(nq + nv, nz) - zdot_;
  }
  r.array() *= equation_scale_.array();
}

void GglDaeForm::algebraic_constraint_scales(VectorX& scale) const {
  const int size = system_.size(), m = kept_rows();
  scale.setZero(dae_size());
  if (m == 0) return;
  // lambda: none. Weighing lambda as well (h (J M^-1 J^T)_ii for J v) doubled Newton's
  // iterations on the 3-hour H1 case for nothing: with Phi held, J v stays at 7e-12.
  scale.segment(size + m, m) = position_row_scale_;
}

std::string GglDaeForm::describe_component(int index) const {
  const int size = system_.size(), m = kept_rows();
  if (index < size) return system_.describe_state_component(index);
  if (index < size + m) return "multiplier of " + describe_constraint_row(system_.model(), rows_[index - size]);
  if (index < size + 2 * m)
    return "position multiplier (GGL mu) of " + describe_constraint_row(system_.model(), rows_[index - size - m]);
  return "component " + std::to_string(index);
}

void GglDaeForm::configuration_maps() {
  const Model& model = system_.model();
  const VectorX& q = system_.configuration();
  N_.setZero(model.nq, model.nv);
  N_plus_.setZero(model.nv, model.nq);
  // Workspaces sized once (the Newton matrix is rebuilt often: no allocation here).
  VectorX& unit = map_unit_;
  VectorX& qdot = map_qdot_;
  VectorX& qdot_zero = map_qdot_zero_;
  unit.setZero(model.nv);
  qdot.resize(model.nq);
  qdot_zero.resize(model.nq);
  configuration_derivative(model, q, unit, qdot_zero);
  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    if (joint.nv == 0) continue;
    if (joint_has_scalar_coordinates(joint.type)) {
      N_.block(joint.q_index, joint.v_index, joint.nq, joint.nv).setIdentity();
      N_plus_.block(joint.v_index, joint.q_index, joint.nv, joint.nq).setIdentity();
      continue;
    }
    // N is linear in v: column k = qdot(q, e_k) - qdot(q, 0); N+ = (N^T N)^-1 N^T.
    for (int k = 0; k < joint.nv; ++k) {
      unit[joint.v_index + k] = 1.0;
      configuration_derivative(model, q, unit, qdot);
      unit[joint.v_index + k] = 0.0;
      N_.block(joint.q_index, joint.v_index + k, joint.nq, 1) = (qdot - qdot_zero).segment(joint.q_index, joint.nq);
    }
    // A joint's map is at most 7 x 6 (the free joint): fixed-capacity matrices, no heap.
    using JointMap = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 7, 6>;
    using JointGram = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;
    const JointMap N = N_.block(joint.q_index, joint.v_index, joint.nq, joint.nv);
    const JointGram gram = N.transpose() * N;
    N_plus_.block(joint.v_index, joint.q_index, joint.nv, joint.nq) = gram.ldlt().solve(N.transpose());
  }
}

bool GglDaeForm::jacobian(double t, const VectorX& y, const VectorX& yp, MatrixX& residual_y, MatrixX& residual_yp) {
  const Model& model = system_.model();
  const int nq = model.nq, nv = model.nv, size = system_.size(), nz = size - nq - nv, m = kept_rows();
  const int iv = nq, iz = nq + nv, il = size, im = size + m;
  residual_y.setZero(dae_size(), dae_size());  // dF/dy
  residual_yp.setZero(dae_size(), dae_size());  // dF/dy': q' and z' appear alone, v' through ID (the mass matrix)

  ggl_derivatives_.mu = y.segment(im, m);
  lambda_ = y.segment(il, m);
  vdot_ = yp.segment(nq, nv);
  differentiator_.differentiate(t, y, vdot_, rows_, lambda_, derivatives_, &ggl_derivatives_);
  configuration_maps();
  const DynamicsDerivatives& d = derivatives_;
  const MatrixX& rows_jacobian = differentiator_.rows_jacobian();
  const VectorX& q = system_.configuration();

  // F_q = q' - N(q) w, w = v - J^T mu.
  w_ = system_.velocity();
  w_.noalias() -= rows_jacobian.transpose() * ggl_derivatives_.mu;
  qdot_.resize(nq);
  configuration_derivative(model, q, w_, qdot_);
  residual_yp.block(0, 0, nq, nq).diagonal().setOnes();
  // d(N(q) w)/dq in raw coordinates: N is constant for plain coordinates, so only the
  // quaternion-carrying joints (spherical, free) have columns here.
  const double h_raw = 1e-7;
  q_perturbed_ = q;
  qdot_plus_.resize(nq);
  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    if (joint.nq == 0 || joint_has_scalar_coordinates(joint.type)) continue;
    for (int k = joint.q_index; k < joint.q_index + joint.nq; ++k) {
      q_perturbed_[k] += h_raw;
      configuration_derivative(model, q_perturbed_, w_, qdot_plus_);
      q_perturbed_[k] = q[k];
      residual_y.block(0, k, nq, 1) -= (qdot_plus_ - qdot_) / h_raw;
    }
  }
  // N (d(J^T mu)/dq) N+, in two products through a kept workspace (a triple product
  // would make a heap temporary at every Newton matrix).
  n_times_jt_mu_q_.noalias() = N_ * ggl_derivatives_.jt_mu_q;
  residual_y.block(0, 0, nq, nq).noalias() += n_times_jt_mu_q_ * N_plus_;
  residual_y.block(0, iv, nq, nv) = -N_;

  // F_v = ID(q, v, v') - Q - J^T lambda;  F_z = z' - g.
  residual_y.block(iv, 0, nv, nq).noalias() = d.force_q * N_plus_;
  residual_y.block(iv, iv, nv, nv) = d.force_v;
  residual_yp.block(iv, iv, nv, nv) = d.mass;
  if (nz > 0) {
    residual_y.block(iv, iz, nv, nz) = d.force_z;
    residual_y.block(iz, 0, nz, nq).noalias() = -d.rate_q * N_plus_;
    residual_y.block(iz, iv, nz, nv) = -d.rate_v;
    residual_y.block(iz, iz, nz, nz) = -d.rate_z;
    residual_yp.block(iz, iz, nz, nz).diagonal().setOnes();
  }
  if (m > 0) residual_y.block(il, 0, m, nq).noalias() = ggl_derivatives_.jv_q * N_plus_;  // d(J v)/dq
  residual_y.array().colwise() *= equation_scale_.array();
  residual_yp.array().colwise() *= equation_scale_.array();
  write_constraint_blocks(rows_jacobian, residual_y);
  return true;
}

void GglDaeForm::write_constraint_blocks(const MatrixX& kept_jacobian, MatrixX& residual_y) {
  const int nq = system_.model().nq, nv = system_.model().nv, size = system_.size(), m = kept_rows();
  if (m == 0) return;
  const int iv = nq, il = size, im = size + m;
  // F_q = q' - N (v - J^T mu), F_v = ID - Q - J^T lambda, F_lambda = J v - nu, F_mu = Phi
  // (Phi_q = J N+), each row scaled by its equation's constant.
  rows_jacobian_in_newton_matrix_ = kept_jacobian;
  auto n_jt = residual_y.block(0, im, nq, m);
  auto jt = residual_y.block(iv, il, nv, m);
  auto j = residual_y.block(il, iv, m, nv);
  auto j_n_plus = residual_y.block(im, 0, m, nq);
  n_jt.noalias() = N_ * kept_jacobian.transpose();
  jt = -kept_jacobian.transpose();
  j = kept_jacobian;
  j_n_plus.noalias() = kept_jacobian * N_plus_;
  n_jt.array().colwise() *= equation_scale_.segment(0, nq).array();
  jt.array().colwise() *= equation_scale_.segment(iv, nv).array();
  j.array().colwise() *= equation_scale_.segment(il, m).array();
  j_n_plus.array().colwise() *= equation_scale_.segment(im, m).array();
}

bool GglDaeForm::refresh_jacobian(MatrixX& residual_y) noexcept {
  // The loops turn with the mechanism, and a J that has turned by a relative d since the
  // matrix was formed makes the position multipliers converge at a rate of about d, too
  // slow for IDA's test beyond a few percent (docs/physics/constraints-and-integration.md
  // §5). On the slider-crank L1 at rtol = atol = 1e-6, with J kept from the last
  // evaluation (0.05-0.3 rad of crank earlier) they converged at 0.04-0.4 and failed
  // the test 47 times in 268 steps. So J's blocks are rewritten from the last residual's
  // J (the Newton iterate's) once a row has moved by 1 % of its largest entry; N and N+
  // (the identity but for quaternions) and the dynamics' derivatives stay those of the
  // last evaluation.
  // Row by row, each against its own largest entry, so that the test does not depend on
  // the units of the rows (metres against radians, long and short lever arms).
  for (int row = 0; row < kept_rows(); ++row) {
    const double largest_entry = rows_jacobian_in_newton_matrix_.row(row).cwiseAbs().maxCoeff();
    if ((rows_jacobian_.row(row) - rows_jacobian_in_newton_matrix_.row(row)).cwiseAbs().maxCoeff() >
        1e-2 * largest_entry) {
      write_constraint_blocks(rows_jacobian_, residual_y);
      return true;
    }
  }
  return false;
}

}  // namespace heavesim
