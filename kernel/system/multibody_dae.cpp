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
// The Newton matrix dF/dy + cj dF/dy' is assembled from the dynamics' partial
// derivatives (dynamics_derivatives.cpp: analytic M, dID/dq, dID/dv; differences for
// the elements and the q-dependence of J^T lambda, J^T mu and J v), J, Phi_q = J N+
// and N. Derivatives in q are taken along tangent directions and mapped to the raw
// coordinates with N+ (unit quaternions: 4 N^T).
#include <Eigen/Cholesky>
#include <Eigen/QR>

#include "kernel/algorithms/configuration.hpp"
#include "kernel/algorithms/constraint_equations.hpp"
#include "kernel/algorithms/projection.hpp"
#include "kernel/system/multibody_system.hpp"

namespace heavesim {

void MultibodySystem::differential_mask(VectorX& mask) const {
  mask.setZero(dae_size());
  mask.head(size_).setOnes();
}

void MultibodySystem::dae_initial_values(double t, const VectorX& state, VectorX& y, VectorX& yp) {
  const Model& model = *model_;
  VectorX ode_rate(size_);
  derivative(t, state, ode_rate);  // qdd and, with loops, lambda from the KKT solve
  dae_rows_.clear();
  if (model.has_constraints()) {
    // The ODE evaluation left the position stage at q and lambda of all rows.
    const ConstraintRank rank = analyse_constraint_rank(model, data_);
    std::vector<bool> redundant(model.num_constraint_rows, false);
    for (int row : rank.redundant_rows) redundant[row] = true;
    for (int row = 0; row < model.num_constraint_rows; ++row)
      if (!redundant[row]) dae_rows_.push_back(row);
  }
  const int kept = dae_rows();
  y.setZero(dae_size());
  yp.setZero(dae_size());
  y.head(size_) = state;
  yp.head(size_) = ode_rate;
  rows_jacobian_.resize(kept, model.nv);
  dae_constraint_.resize(kept);
  if (kept == 0) return;
  // Multipliers of the kept rows giving the same constraint force J^T lambda (mu = 0).
  const MatrixX J_kept = data_.constraint_jacobian(dae_rows_, Eigen::all);
  const VectorX generalized_force = data_.constraint_jacobian.transpose() * data_.constraint_multipliers;
  y.segment(size_, kept) = J_kept.transpose().colPivHouseholderQr().solve(generalized_force);
}

void MultibodySystem::residual(double t, const VectorX& y, const VectorX& yp, VectorX& r) {
  const Model& model = *model_;
  const int nq = model.nq, nv = model.nv, nz = size_ - nq - nv, m = dae_rows();
  q_ = y.head(nq);
  v_ = y.segment(nq, nv);
  dae_vdot_ = yp.segment(nq, nv);
  compute_stages_and_forces(t, y);
  r.segment(nq, nv) = inverse_dynamics(model, data_, dae_vdot_, forces_.external_force_world);
  r.segment(nq, nv) -= forces_.joint_force;
  dae_w_ = v_;
  if (m > 0) {
    constraint_jacobian(model, data_, data_.constraint_jacobian);
    constraint_residual(model, data_, q_, t, data_.constraint_residual);
    constraint_velocity_target(model, t, data_.constraint_velocity_target);
    rows_jacobian_ = data_.constraint_jacobian(dae_rows_, Eigen::all);
    dae_constraint_ = data_.constraint_residual(dae_rows_);
    r.segment(nq, nv).noalias() -= rows_jacobian_.transpose() * y.segment(size_, m);
    dae_w_.noalias() -= rows_jacobian_.transpose() * y.segment(size_ + m, m);
    r.segment(size_, m).noalias() = rows_jacobian_ * v_;
    r.segment(size_, m) -= data_.constraint_velocity_target(dae_rows_);
    r.segment(size_ + m, m) = dae_constraint_;
  }
  dae_qdot_.resize(nq);
  configuration_derivative(model, q_, dae_w_, dae_qdot_);
  r.head(nq) = yp.head(nq) - dae_qdot_;
  if (nz > 0) {
    dae_zdot_.resize(nz);
    element_state_derivatives(t, y, data_, dae_zdot_);
    r.segment(nq + nv, nz) = yp.segment(nq + nv, nz) - dae_zdot_;
  }
}

void MultibodySystem::configuration_maps() {
  const Model& model = *model_;
  dae_N_.setZero(model.nq, model.nv);
  dae_N_plus_.setZero(model.nv, model.nq);
  VectorX unit = VectorX::Zero(model.nv), qdot(model.nq), qdot_zero(model.nq);
  configuration_derivative(model, q_, unit, qdot_zero);
  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    if (joint.nv == 0) continue;
    if (joint_has_scalar_coordinates(joint.type)) {
      dae_N_.block(joint.q_index, joint.v_index, joint.nq, joint.nv).setIdentity();
      dae_N_plus_.block(joint.v_index, joint.q_index, joint.nv, joint.nq).setIdentity();
      continue;
    }
    // N is linear in v: column k = qdot(q, e_k) - qdot(q, 0); N+ = (N^T N)^-1 N^T.
    for (int k = 0; k < joint.nv; ++k) {
      unit[joint.v_index + k] = 1.0;
      configuration_derivative(model, q_, unit, qdot);
      unit[joint.v_index + k] = 0.0;
      dae_N_.block(joint.q_index, joint.v_index + k, joint.nq, 1) =
          (qdot - qdot_zero).segment(joint.q_index, joint.nq);
    }
    const MatrixX N = dae_N_.block(joint.q_index, joint.v_index, joint.nq, joint.nv);
    dae_N_plus_.block(joint.v_index, joint.q_index, joint.nv, joint.nq) = (N.transpose() * N).ldlt().solve(N.transpose());
  }
}

bool MultibodySystem::jacobian(double t, const VectorX& y, const VectorX& yp, double cj, MatrixX& J) {
  const Model& model = *model_;
  const int nq = model.nq, nv = model.nv, nz = size_ - nq - nv, m = dae_rows();
  const int iv = nq, iz = nq + nv, il = size_, im = size_ + m;
  J.setZero(dae_size(), dae_size());

  ggl_derivatives_.mu = y.segment(im, m);
  dae_lambda_ = y.segment(il, m);
  dae_vdot_ = yp.segment(nq, nv);
  differentiate_dynamics(t, y, dae_vdot_, dae_rows_, dae_lambda_, derivatives_, &ggl_derivatives_);
  configuration_maps();
  const DynamicsDerivatives& d = derivatives_;

  // F_q = q' - N(q) w, w = v - J^T mu.
  dae_w_ = v_;
  dae_w_.noalias() -= rows_jacobian_.transpose() * ggl_derivatives_.mu;
  dae_qdot_.resize(nq);
  configuration_derivative(model, q_, dae_w_, dae_qdot_);
  J.block(0, 0, nq, nq).diagonal().setConstant(cj);
  // d(N(q) w)/dq in raw coordinates: N is constant for plain coordinates, so only the
  // quaternion-carrying joints (spherical, free) have columns here.
  const double h_raw = 1e-7;
  q_perturbed_ = q_;
  dae_qdot_plus_.resize(nq);
  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    if (joint.nq == 0 || joint_has_scalar_coordinates(joint.type)) continue;
    for (int k = joint.q_index; k < joint.q_index + joint.nq; ++k) {
      q_perturbed_[k] += h_raw;
      configuration_derivative(model, q_perturbed_, dae_w_, dae_qdot_plus_);
      q_perturbed_[k] = q_[k];
      J.block(0, k, nq, 1) -= (dae_qdot_plus_ - dae_qdot_) / h_raw;
    }
  }
  J.block(0, 0, nq, nq).noalias() += dae_N_ * ggl_derivatives_.jt_mu_q * dae_N_plus_;
  J.block(0, iv, nq, nv) = -dae_N_;

  // F_v = ID(q, v, v') - Q - J^T lambda;  F_z = z' - g.
  J.block(iv, 0, nv, nq).noalias() = d.force_q * dae_N_plus_;
  J.block(iv, iv, nv, nv) = d.force_v + cj * d.mass;
  if (nz > 0) {
    J.block(iv, iz, nv, nz) = d.force_z;
    J.block(iz, 0, nz, nq).noalias() = -d.rate_q * dae_N_plus_;
    J.block(iz, iv, nz, nv) = -d.rate_v;
    J.block(iz, iz, nz, nz) = -d.rate_z;
    J.block(iz, iz, nz, nz).diagonal().array() += cj;
  }
  if (m > 0) {
    // F_lambda = J v - nu, F_mu = Phi.
    J.block(0, im, nq, m).noalias() = dae_N_ * rows_jacobian_.transpose();
    J.block(iv, il, nv, m) = -rows_jacobian_.transpose();
    J.block(il, 0, m, nq).noalias() = ggl_derivatives_.jv_q * dae_N_plus_;
    J.block(il, iv, m, nv) = rows_jacobian_;
    J.block(im, 0, m, nq).noalias() = rows_jacobian_ * dae_N_plus_;
  }
  return true;
}

}  // namespace heavesim
