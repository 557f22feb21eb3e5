// MultibodySystem as a SecondOrderSystem (second_order_system.hpp): the equations of
// motion with every constraint row, for the index-3 augmented-Lagrangian HHT
// integrator. Redundant rows need no special care there (the augmented Lagrangian
// never inverts J M^-1 J^T), so unlike the GGL form nothing is dropped.
#include "kernel/algorithms/configuration.hpp"
#include "kernel/algorithms/inverse_dynamics.hpp"
#include "kernel/algorithms/mass_matrix.hpp"
#include "kernel/algorithms/constraint_equations.hpp"
#include "kernel/system/multibody_system.hpp"

namespace heavesim {

void MultibodySystem::integrate_configuration(const VectorX& q, const VectorX& step, VectorX& q_out) const {
  heavesim::integrate_configuration(*model_, q, step, 1.0, q_out);
}

void MultibodySystem::initial_accelerations(double t, const VectorX& y, VectorX& a, VectorX& zdot,
                                            VectorX& lambda) {
  const Model& model = *model_;
  const int nq = model.nq, nv = model.nv;
  initial_rate_.resize(size_);
  derivative(t, y, initial_rate_);  // the KKT solve: qdd and lambda
  a = initial_rate_.segment(nq, nv);
  zdot = initial_rate_.tail(size_ - nq - nv);
  lambda = data_.constraint_multipliers;
}

void MultibodySystem::dynamics_residual(double t, const VectorX& y, const VectorX& a, const VectorX& zdot,
                                        double penalty, VectorX& lambda,
                                        Eigen::Ref<VectorX> r_v, Eigen::Ref<VectorX> r_z, Eigen::Ref<VectorX> phi) {
  const Model& model = *model_;
  const int nq = model.nq, nv = model.nv, nz = size_ - nq - nv;
  q_ = y.head(nq);
  v_ = y.segment(nq, nv);
  compute_stages_and_forces(t, y);
  r_v = inverse_dynamics(model, data_, a, forces_.external_force_world);
  r_v -= forces_.joint_force;
  if (model.has_constraints()) {
    constraint_jacobian(model, data_, data_.constraint_jacobian);
    constraint_residual(model, data_, q_, t, phi);
    // Bayo & Ledesma: lambda* += -p Phi(q) on arriving at q, then the force is
    // J^T (lambda* - p Phi). (Updating after the residual instead makes the iteration
    // a barely damped oscillation of period 6.)
    lambda -= penalty * phi;
    multiplier_force_ = lambda - penalty * phi;
    r_v.noalias() -= data_.constraint_jacobian.transpose() * multiplier_force_;
  }
  if (nz > 0) {
    element_state_derivatives(t, y, data_, r_z);
    r_z = zdot - r_z;
  }
  if (!r_v.allFinite() || !r_z.allFinite()) report_non_finite(t, r_v, "the equation of motion");
}

void MultibodySystem::dynamics_derivatives(double t, const VectorX& y, const VectorX& a, DynamicsDerivatives& out) {
  static const std::vector<int> no_rows;
  static const VectorX no_multipliers;
  differentiate_dynamics(t, y, a, no_rows, no_multipliers, out, nullptr);
}

void MultibodySystem::constraint_terms(double t, const VectorX& y, ConstraintTerms& out) {
  const Model& model = *model_;
  q_ = y.head(model.nq);
  v_ = y.segment(model.nq, model.nv);
  update_positions(model, data_, q_);
  update_velocities(model, data_, q_, v_);
  out.mass = mass_matrix(model, data_);
  const int m = model.num_constraint_rows;
  out.jacobian.resize(m, model.nv);
  out.residual.resize(m);
  out.velocity_target.resize(m);
  out.bias.resize(m);
  if (m == 0) return;
  constraint_jacobian(model, data_, out.jacobian);
  constraint_residual(model, data_, q_, t, out.residual);
  constraint_velocity_target(model, t, out.velocity_target);
  constraint_bias(model, data_, t, out.bias);
}

void MultibodySystem::constraint_bias_at(double t, const VectorX& y, VectorX& gamma) {
  const Model& model = *model_;
  q_ = y.head(model.nq);
  v_ = y.segment(model.nq, model.nv);
  update_positions(model, data_, q_);
  update_velocities(model, data_, q_, v_);
  gamma.resize(model.num_constraint_rows);
  if (model.has_constraints()) constraint_bias(model, data_, t, gamma);
}

}  // namespace heavesim
