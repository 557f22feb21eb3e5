// Partial derivatives of the multibody equations of motion, shared by IDA's Newton
// matrix (multibody_dae.cpp) and the index-3 HHT integrator (second_order_form.cpp).
//
// Analytic where the kernel can differentiate -- the mass matrix (CRBA), dID/dq and
// dID/dv (inverse_dynamics_derivatives) -- and forward differences (step 1e-7) where
// it cannot: the force elements and joint elements (their dependence on q, v, z) and
// the q-dependence of J^T lambda. Derivatives in q are along the tangent directions of
// integrate_configuration.
#include "kernel/algorithms/configuration.hpp"
#include "kernel/algorithms/inverse_dynamics_derivatives.hpp"
#include "kernel/algorithms/joint_forces.hpp"
#include "kernel/algorithms/mass_matrix.hpp"
#include "kernel/algorithms/constraint_equations.hpp"
#include "kernel/system/multibody_system.hpp"

namespace heavesim {

void MultibodySystem::generalized_applied_force(const Data& base, const AppliedForces& forces, VectorX& out) {
  // Q = tau + sum_i J_i^T f_i with the base configuration's subspaces: backward sums.
  const Model& model = *model_;
  subtree_forces_ = forces.external_force_world;
  out = forces.joint_force;
  for (int i = model.num_links() - 1; i >= 1; --i) {
    const Joint& joint = model.joints[i];
    for (int c = 0; c < joint.nv; ++c)
      out[joint.v_index + c] += dot(base.motion_subspace_world.col(joint.v_index + c), subtree_forces_[i]);
    if (joint.parent > 0) subtree_forces_[joint.parent] += subtree_forces_[i];
  }
}

bool MultibodySystem::has_applied_state_dependence() const {
  if (!elements_.empty()) return true;
  for (int i = 1; i < model_->num_links(); ++i)
    if (model_->joints[i].spring || model_->joints[i].limits) return true;
  return false;
}

void MultibodySystem::applied_forces_at(double t, const Data& stages, const VectorX& q, const VectorX& v,
                                        const VectorX& y) {
  const Model& model = *model_;
  scratch_forces_.clear();
  add_joint_element_forces(model, q, v, scratch_forces_.joint_force);
  for (std::size_t e = 0; e < elements_.size(); ++e)
    elements_[e]->apply(t, model, stages, y.segment(state_offsets_[e], elements_[e]->state_size()), scratch_forces_);
}

void MultibodySystem::differentiate_dynamics(double t, const VectorX& y, const VectorX& a,
                                             const std::vector<int>& rows, const VectorX& lambda,
                                             DynamicsDerivatives& out, GglDerivatives* ggl) {
  const Model& model = *model_;
  const int nq = model.nq, nv = model.nv, nz = size_ - nq - nv, m = static_cast<int>(rows.size());
  q_ = y.head(nq);
  v_ = y.segment(nq, nv);
  compute_stages_and_forces(t, y);
  if (m > 0) {
    constraint_jacobian(model, data_, data_.constraint_jacobian);
    rows_jacobian_ = data_.constraint_jacobian(rows, Eigen::all);
  }
  out.mass.resize(nv, nv);
  out.force_z.setZero(nv, nz);
  out.rate_q.setZero(nz, nv);
  out.rate_v.setZero(nz, nv);
  out.rate_z.setZero(nz, nz);
  if (ggl) {
    ggl->jt_mu_q.setZero(nv, nv);
    ggl->jv_q.setZero(m, nv);
  }
  inverse_dynamics_derivatives(model, data_, q_, v_, a, forces_.external_force_world);
  out.force_q = data_.dtau_dq;
  out.force_v = data_.dtau_dv;
  out.mass = mass_matrix(model, data_);

  const bool applied = has_applied_state_dependence();
  if (!applied && m == 0) return;
  constexpr double h = 1e-7;
  q_perturbed_.resize(nq);
  rates_base_.resize(nz);
  rates_perturbed_.resize(nz);
  if (applied) generalized_applied_force(data_, forces_, applied_base_);
  if (nz > 0) element_state_derivatives(t, y, data_, rates_base_);
  // Configuration: one tangent direction at a time.
  direction_.setZero(nv);
  for (int k = 0; k < nv; ++k) {
    direction_[k] = 1.0;
    heavesim::integrate_configuration(model, q_, direction_, h, q_perturbed_);
    direction_[k] = 0.0;
    update_positions(model, scratch_data_, q_perturbed_);
    if (m > 0) {
      constraint_jacobian(model, scratch_data_, scratch_data_.constraint_jacobian);
      jacobian_change_ = scratch_data_.constraint_jacobian(rows, Eigen::all);
      jacobian_change_ -= rows_jacobian_;
      jacobian_change_ /= h;  // dJ/d(tangent k)
      out.force_q.col(k).noalias() -= jacobian_change_.transpose() * lambda;
      if (ggl) {
        ggl->jt_mu_q.col(k).noalias() = jacobian_change_.transpose() * ggl->mu;
        ggl->jv_q.col(k).noalias() = jacobian_change_ * v_;
      }
    }
    if (applied) {
      update_velocities(model, scratch_data_, q_perturbed_, v_);
      applied_forces_at(t, scratch_data_, q_perturbed_, v_, y);
      generalized_applied_force(data_, scratch_forces_, applied_perturbed_);
      out.force_q.col(k) -= (applied_perturbed_ - applied_base_) / h;
      if (nz > 0) {
        element_state_derivatives(t, y, scratch_data_, rates_perturbed_);
        out.rate_q.col(k) = (rates_perturbed_ - rates_base_) / h;
      }
    }
  }
  if (!applied) return;
  // Speeds and element states, at the base configuration.
  v_perturbed_ = v_;
  y_perturbed_ = y;
  update_positions(model, scratch_data_, q_);
  for (int k = 0; k < nv + nz; ++k) {
    const bool speed = k < nv;
    if (speed)
      v_perturbed_[k] += h;
    else
      y_perturbed_[nq + k] += h;
    update_velocities(model, scratch_data_, q_, v_perturbed_);
    applied_forces_at(t, scratch_data_, q_, v_perturbed_, y_perturbed_);
    generalized_applied_force(data_, scratch_forces_, applied_perturbed_);
    (speed ? out.force_v.col(k) : out.force_z.col(k - nv)) -= (applied_perturbed_ - applied_base_) / h;
    if (nz > 0) {
      element_state_derivatives(t, y_perturbed_, scratch_data_, rates_perturbed_);
      (speed ? out.rate_v.col(k) : out.rate_z.col(k - nv)) = (rates_perturbed_ - rates_base_) / h;
    }
    if (speed)
      v_perturbed_[k] = v_[k];
    else
      y_perturbed_[nq + k] = y[nq + k];
  }
}

}  // namespace heavesim
