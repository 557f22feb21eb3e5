#include "kernel/system/dynamics_differentiator.hpp"

#include "kernel/algorithms/configuration.hpp"
#include "kernel/algorithms/constraint_equations.hpp"
#include "kernel/algorithms/generalized_force.hpp"
#include "kernel/algorithms/inverse_dynamics_derivatives.hpp"
#include "kernel/algorithms/mass_matrix.hpp"
#include "kernel/math/index_list.hpp"

namespace heavesim {

DynamicsDifferentiator::DynamicsDifferentiator(MultibodySystem& system)
    : system_(system),
      scratch_data_(system.model()),
      scratch_forces_(system.model()),
      rows_jacobian_(MatrixX::Zero(0, system.model().nv)),
      subtree_forces_(system.model().num_links(), Force::Zero()) {}

void DynamicsDifferentiator::generalized_force(const Data& base, const AppliedForces& forces, VectorX& out) {
  generalized_applied_force(system_.model(), base, forces.external_force_world, forces.joint_force, subtree_forces_,
                            out);
}

void DynamicsDifferentiator::column_of_every_element(double t, const VectorX& q, const VectorX& v, const VectorX& y,
                                                     double h, Eigen::Ref<VectorX> force_column,
                                                     Eigen::Ref<VectorX> rate_column) {
  MultibodySystem& system = system_;
  system.applied_forces_at(t, scratch_data_, q, v, y, scratch_forces_);
  generalized_force(system.data(), scratch_forces_, applied_perturbed_);
  force_column -= (applied_perturbed_ - applied_base_) / h;
  if (rate_column.size() == 0) return;
  system.element_state_derivatives(t, y, scratch_data_, rates_perturbed_);
  rate_column = (rates_perturbed_ - rates_base_) / h;
}

void DynamicsDifferentiator::differentiate(double t, const VectorX& y, const VectorX& a, const std::vector<int>& rows,
                                           const VectorX& lambda, DynamicsDerivatives& out, GglDerivatives* ggl) {
  MultibodySystem& system = system_;
  const Model& model = system.model();
  Data& data = system.mutable_data();
  const int nq = model.nq, nv = model.nv, nz = system.element_state_size(), m = static_cast<int>(rows.size());
  system.compute_stages_and_forces(t, y);
  const VectorX& q = system.configuration();
  const VectorX& v = system.velocity();
  if (m > 0) {
    constraint_jacobian(model, data, t, data.constraint_jacobian);
    rows_jacobian_ = data.constraint_jacobian(index_list(rows), Eigen::all);
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
  inverse_dynamics_derivatives(model, data, q, v, a, system.applied_forces().external_force_world);
  out.force_q = data.dtau_dq;
  out.force_v = data.dtau_dv;
  out.mass = mass_matrix(model, data);

  // Column groups that no element (nor joint element) depends on are exactly zero and
  // are skipped (ElementDependencies).
  const ElementDependencies& depends = system.applied_dependencies();
  const bool applied = system.has_applied_state_dependence();
  if (!applied && m == 0) return;
  constexpr double h = 1e-7;
  q_perturbed_.resize(nq);
  rates_base_.resize(nz);
  rates_perturbed_.resize(nz);
  if (applied) generalized_force(data, system.applied_forces(), applied_base_);
  if (nz > 0) system.element_state_derivatives(t, y, data, rates_base_);
  // Configuration: one tangent direction at a time.
  direction_.setZero(nv);
  for (int k = 0; k < nv; ++k) {
    direction_[k] = 1.0;
    integrate_configuration(model, q, direction_, h, q_perturbed_);
    direction_[k] = 0.0;
    update_positions(model, scratch_data_, q_perturbed_);
    if (m > 0) {
      constraint_jacobian(model, scratch_data_, t, scratch_data_.constraint_jacobian);
      jacobian_change_ = scratch_data_.constraint_jacobian(index_list(rows), Eigen::all);
      jacobian_change_ -= rows_jacobian_;
      jacobian_change_ /= h;  // dJ/d(tangent k)
      out.force_q.col(k).noalias() -= jacobian_change_.transpose() * lambda;
      if (ggl) {
        ggl->jt_mu_q.col(k).noalias() = jacobian_change_.transpose() * ggl->mu;
        ggl->jv_q.col(k).noalias() = jacobian_change_ * v;
      }
    }
    if (depends.configuration) {
      update_velocities(model, scratch_data_, q_perturbed_, v);
      column_of_every_element(t, q_perturbed_, v, y, h, out.force_q.col(k), out.rate_q.col(k));
    }
  }
  if (!applied) return;
  // Speeds, at the base configuration.
  v_perturbed_ = v;
  update_positions(model, scratch_data_, q);
  if (depends.velocity) {
    for (int k = 0; k < nv; ++k) {
      v_perturbed_[k] += h;
      update_velocities(model, scratch_data_, q, v_perturbed_);
      column_of_every_element(t, q, v_perturbed_, y, h, out.force_v.col(k), out.rate_v.col(k));
      v_perturbed_[k] = v[k];
    }
  }
  if (!depends.element_states || nz == 0) return;
  // Element states. An element is given only its own states (ForceElement::apply and
  // state_derivative take its slice of y), so a state's column changes only its own
  // element's load and rates: each column evaluates that element alone, against that
  // element's load at the base state. The quotient is the same as that of every element's
  // total; on the H1 rig 5 of the Newton matrix's 21 difference columns re-evaluated all 7
  // elements and the velocity stage.
  update_velocities(model, scratch_data_, q, v);
  y_perturbed_ = y;
  const auto& elements = system.force_elements();
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const ForceElement& element = *elements[e];
    const int size = element.state_size();
    if (size == 0) continue;
    const int offset = system.state_offset(e), column = offset - nq - nv;  // in y, in z
    scratch_forces_.clear();
    element.apply(t, model, scratch_data_, y.segment(offset, size), scratch_forces_);
    generalized_force(data, scratch_forces_, element_base_);
    for (int j = 0; j < size; ++j) {
      y_perturbed_[offset + j] += h;
      const auto states = y_perturbed_.segment(offset, size);
      scratch_forces_.clear();
      element.apply(t, model, scratch_data_, states, scratch_forces_);
      generalized_force(data, scratch_forces_, applied_perturbed_);
      out.force_z.col(column + j) -= (applied_perturbed_ - element_base_) / h;
      auto rates = rates_perturbed_.segment(column, size);
      element.state_derivative(t, model, scratch_data_, states, rates);
      out.rate_z.col(column + j).segment(column, size) = (rates - rates_base_.segment(column, size)) / h;
      y_perturbed_[offset + j] = y[offset + j];
    }
  }
}

}  // namespace heavesim
