// The stabilized index-2 form of a multibody model for IDA (Gear, Gupta & Leimkuhler
// 1985; the form of SUNDIALS' idaSlCrank example), y = [q; v; z; lambda; mu]:
//   F_q  = q' - N(q) (v - J^T mu)         mu keeps q on Phi = 0 (mu = 0 at the solution)
//   F_v  = ID(q, v, v') - tau - J^T lambda  one RNEA pass: no forward dynamics
//   F_z  = z' - g(t, q, v, z)
//   F_lambda = J v                          velocity-level constraints
//   F_mu = Phi(q)                           position-level constraints
// lambda and mu are algebraic (excluded from IDA's error test).
//
// Redundant constraint rows (a planar loop closed by a 3-D revolute joint, two
// parallel rods on one block) would make the Newton matrix singular: the DAE keeps
// only the independent rows found by the rank-revealing QR at the initial state
// (analyse_constraint_rank), as multibody codes do; the others then hold by
// themselves. Reported multipliers still come from evaluate(), the minimum-norm
// solution over all rows.
//
// The Newton matrix dF/dy + cj dF/dy' is assembled from analytic parts -- the mass
// matrix (CRBA), dID/dq and dID/dv (inverse_dynamics_derivatives), J, Phi_q = J N+,
// N -- and forward differences only where the kernel cannot differentiate: the force
// elements and joint elements (their dependence on q, v, z), and the q-dependence of
// J^T lambda and J v. Derivatives in q are taken along tangent directions and mapped
// to the raw coordinates with N+ (unit quaternions: 4 N^T).
#include <Eigen/Cholesky>
#include <Eigen/QR>

#include "kernel/algorithms/configuration.hpp"
#include "kernel/algorithms/inverse_dynamics_derivatives.hpp"
#include "kernel/algorithms/joint_forces.hpp"
#include "kernel/constraints/constraint_equations.hpp"
#include "kernel/constraints/projection.hpp"
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
  dae_jacobian_.resize(kept, model.nv);
  dae_constraint_.resize(kept);
  dae_jacobian_plus_.resize(kept, model.nv);
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
    constraint_residual(model, data_, q_, data_.constraint_residual);
    dae_jacobian_ = data_.constraint_jacobian(dae_rows_, Eigen::all);
    dae_constraint_ = data_.constraint_residual(dae_rows_);
    r.segment(nq, nv).noalias() -= dae_jacobian_.transpose() * y.segment(size_, m);
    dae_w_.noalias() -= dae_jacobian_.transpose() * y.segment(size_ + m, m);
    r.segment(size_, m).noalias() = dae_jacobian_ * v_;
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

void MultibodySystem::generalized_applied_force(const Data& base, const AppliedForces& forces, VectorX& out) {
  // Q = tau + sum_i J_i^T f_i with the base configuration's subspaces: backward sums.
  const Model& model = *model_;
  dae_subtree_forces_ = forces.external_force_world;
  out = forces.joint_force;
  for (int i = model.num_links() - 1; i >= 1; --i) {
    const Joint& joint = model.joints[i];
    for (int c = 0; c < joint.nv; ++c)
      out[joint.v_index + c] += dot(base.motion_subspace_world.col(joint.v_index + c), dae_subtree_forces_[i]);
    if (joint.parent > 0) dae_subtree_forces_[joint.parent] += dae_subtree_forces_[i];
  }
}

bool MultibodySystem::has_applied_state_dependence() const {
  if (!elements_.empty()) return true;
  for (int i = 1; i < model_->num_links(); ++i)
    if (model_->joints[i].spring || model_->joints[i].limits) return true;
  return false;
}

bool MultibodySystem::jacobian(double t, const VectorX& y, const VectorX& yp, double cj, MatrixX& J) {
  const Model& model = *model_;
  const int nq = model.nq, nv = model.nv, nz = size_ - nq - nv, m = dae_rows();
  const int iv = nq, iz = nq + nv, il = size_, im = size_ + m;
  J.setZero(dae_size(), dae_size());

  // Stages, forces, J and Phi at (q, v) as in the residual.
  VectorX r(dae_size());
  residual(t, y, yp, r);
  configuration_maps();
  const auto lambda = y.segment(il, m);
  const auto mu = y.segment(im, m);
  MatrixX dFq_dtangent = MatrixX::Zero(nq, nv);  // N d(J^T mu)/d(tangent)

  // F_q = q' - N(q) w, w = v - J^T mu (the q-dependence of J^T mu is added below).
  J.block(0, 0, nq, nq).diagonal().setConstant(cj);
  const double h_raw = 1e-7;
  dae_q_plus_ = q_;
  dae_qdot_plus_.resize(nq);
  // d(N(q) w)/dq in raw coordinates: N is constant for plain coordinates, so only the
  // quaternion-carrying joints (spherical, free) have columns here.
  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    if (joint.nq == 0 || joint_has_scalar_coordinates(joint.type)) continue;
    for (int k = joint.q_index; k < joint.q_index + joint.nq; ++k) {
      dae_q_plus_[k] += h_raw;
      configuration_derivative(model, dae_q_plus_, dae_w_, dae_qdot_plus_);
      dae_q_plus_[k] = q_[k];
      J.block(0, k, nq, 1) -= (dae_qdot_plus_ - dae_qdot_) / h_raw;
    }
  }
  J.block(0, iv, nq, nv) = -dae_N_;

  // F_v = ID(q, v, v') - tau - J^T lambda.
  inverse_dynamics_derivatives(model, data_, q_, v_, dae_vdot_, forces_.external_force_world);
  MatrixX dFv_dtangent = data_.dtau_dq;  // nv x nv, completed below
  J.block(iv, iv, nv, nv) = data_.dtau_dv + cj * mass_matrix(model, data_);

  // Tangent-direction finite differences for what the kernel does not differentiate.
  const bool applied = has_applied_state_dependence();
  if (applied || m > 0) {
    const double h = 1e-7;
    dae_applied_.resize(nv);
    if (applied) generalized_applied_force(data_, forces_, dae_applied_);
    if (nz > 0) {
      dae_zdot_.resize(nz);
      element_state_derivatives(t, y, data_, dae_zdot_);
    }
    VectorX direction = VectorX::Zero(nv);
    for (int k = 0; k < nv; ++k) {
      direction[k] = 1.0;
      integrate_configuration(model, q_, direction, h, dae_q_plus_);
      direction[k] = 0.0;
      update_positions(model, scratch_data_, dae_q_plus_);
      if (m > 0) {
        constraint_jacobian(model, scratch_data_, scratch_data_.constraint_jacobian);
        dae_jacobian_plus_ = scratch_data_.constraint_jacobian(dae_rows_, Eigen::all);
        dae_jacobian_plus_ -= dae_jacobian_;
        dae_jacobian_plus_ /= h;  // dJ/d(tangent k)
        dFv_dtangent.col(k).noalias() -= dae_jacobian_plus_.transpose() * lambda;
        dFq_dtangent.col(k).noalias() = dae_N_ * (dae_jacobian_plus_.transpose() * mu);
        J.block(il, 0, m, nq).noalias() += (dae_jacobian_plus_ * v_) * dae_N_plus_.row(k);
      }
      if (applied) {
        update_velocities(model, scratch_data_, dae_q_plus_, v_);
        scratch_forces_.clear();
        add_joint_element_forces(model, dae_q_plus_, v_, scratch_forces_.joint_force);
        for (std::size_t e = 0; e < elements_.size(); ++e)
          elements_[e]->apply(t, model, scratch_data_, y.segment(state_offsets_[e], elements_[e]->state_size()),
                              scratch_forces_);
        generalized_applied_force(data_, scratch_forces_, dae_applied_plus_);
        dFv_dtangent.col(k) -= (dae_applied_plus_ - dae_applied_) / h;
        if (nz > 0) {
          dae_zdot_plus_.resize(nz);
          element_state_derivatives(t, y, scratch_data_, dae_zdot_plus_);
          J.block(iz, 0, nz, nq).noalias() -= ((dae_zdot_plus_ - dae_zdot_) / h) * dae_N_plus_.row(k);
        }
      }
    }
    if (applied) {
      // Speeds and element states: the base configuration, perturbed v or z.
      VectorX v_plus = v_;
      VectorX y_plus = y;
      update_positions(model, scratch_data_, q_);
      for (int k = 0; k < nv + nz; ++k) {
        const bool speed = k < nv;
        if (speed)
          v_plus[k] += h;
        else
          y_plus[iz + k - nv] += h;
        update_velocities(model, scratch_data_, q_, v_plus);
        scratch_forces_.clear();
        add_joint_element_forces(model, q_, speed ? v_plus : v_, scratch_forces_.joint_force);
        for (std::size_t e = 0; e < elements_.size(); ++e)
          elements_[e]->apply(t, model, scratch_data_,
                              y_plus.segment(state_offsets_[e], elements_[e]->state_size()), scratch_forces_);
        generalized_applied_force(data_, scratch_forces_, dae_applied_plus_);
        J.col(speed ? iv + k : iz + k - nv).segment(iv, nv) -= (dae_applied_plus_ - dae_applied_) / h;
        if (nz > 0) {
          dae_zdot_plus_.resize(nz);
          element_state_derivatives(t, y_plus, scratch_data_, dae_zdot_plus_);
          J.col(speed ? iv + k : iz + k - nv).segment(iz, nz) -= (dae_zdot_plus_ - dae_zdot_) / h;
        }
        if (speed)
          v_plus[k] = v_[k];
        else
          y_plus[iz + k - nv] = y[iz + k - nv];
      }
      if (nz > 0) J.block(iz, iz, nz, nz).diagonal().array() += cj;
    }
  } else if (nz > 0) {
    J.block(iz, iz, nz, nz).diagonal().setConstant(cj);
  }
  J.block(iv, 0, nv, nq).noalias() = dFv_dtangent * dae_N_plus_;
  J.block(0, 0, nq, nq).noalias() += dFq_dtangent * dae_N_plus_;

  if (m > 0) {
    J.block(0, im, nq, m).noalias() = dae_N_ * dae_jacobian_.transpose();
    J.block(iv, il, nv, m) = -dae_jacobian_.transpose();
    J.block(il, iv, m, nv) = dae_jacobian_;
    J.block(im, 0, m, nq).noalias() = dae_jacobian_ * dae_N_plus_;
  }
  return true;
}

}  // namespace heavesim
