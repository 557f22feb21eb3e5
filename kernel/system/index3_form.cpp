#include "kernel/system/index3_form.hpp"

#include "kernel/algorithms/configuration.hpp"
#include "kernel/algorithms/constraint_equations.hpp"
#include "kernel/algorithms/inverse_dynamics.hpp"
#include "kernel/algorithms/mass_matrix.hpp"
#include "kernel/algorithms/projection.hpp"

namespace heavesim {

Index3Form::Index3Form(MultibodySystem& system) : system_(system), differentiator_(system) {}

void Index3Form::integrate_configuration(const VectorX& q, const VectorX& step, VectorX& q_out) const {
  heavesim::integrate_configuration(system_.model(), q, step, 1.0, q_out);
}

void Index3Form::initial_accelerations(double t, const VectorX& y, VectorX& a, VectorX& zdot, VectorX& lambda) {
  const Model& model = system_.model();
  const int nq = model.nq, nv = model.nv, size = system_.size();
  initial_rate_.resize(size);
  system_.state_derivative(t, y, initial_rate_);  // the KKT solve: qdd and lambda
  a = initial_rate_.segment(nq, nv);
  zdot = initial_rate_.tail(size - nq - nv);
  lambda = system_.data().constraint_multipliers;
  independent_rows_.clear();
  if (!model.has_constraints()) return;
  const ConstraintRank rank = analyse_constraint_rank(model, system_.mutable_data(), t);
  independent_rows_ = rank.independent_rows();
  system_.remember_constraint_rank(rank.rank);  // the reference rank for diagnoses
}

void Index3Form::dynamics_residual(double t, const VectorX& y, const VectorX& a, const VectorX& zdot, double penalty,
                                   VectorX& lambda, Eigen::Ref<VectorX> r_v, Eigen::Ref<VectorX> r_z,
                                   Eigen::Ref<VectorX> phi) {
  const Model& model = system_.model();
  Data& data = system_.mutable_data();
  const int nz = system_.element_state_size();
  system_.compute_stages_and_forces(t, y);
  const AppliedForces& forces = system_.applied_forces();
  r_v = inverse_dynamics(model, data, a, forces.external_force_world);
  r_v -= forces.joint_force;
  if (model.has_constraints()) {
    constraint_jacobian(model, data, t, data.constraint_jacobian);
    constraint_residual(model, data, system_.configuration(), t, phi);
    // Bayo & Ledesma: lambda* += -p Phi(q) on arriving at q, then the force is
    // J^T (lambda* - p Phi). (Updating after the residual instead makes the iteration
    // a barely damped oscillation of period 6.)
    lambda -= penalty * phi;
    multiplier_force_ = lambda - penalty * phi;
    r_v.noalias() -= data.constraint_jacobian.transpose() * multiplier_force_;
  }
  if (nz > 0) {
    system_.element_state_derivatives(t, y, data, r_z);
    r_z = zdot - r_z;
  }
  if (!r_v.allFinite() || !r_z.allFinite()) system_.report_non_finite(t, r_v, "the equation of motion");
}

void Index3Form::dynamics_derivatives(double t, const VectorX& y, const VectorX& a, DynamicsDerivatives& out) {
  static const std::vector<int> no_rows;
  static const VectorX no_multipliers;
  differentiator_.differentiate(t, y, a, no_rows, no_multipliers, out, nullptr);
}

void Index3Form::constraint_terms(double t, const VectorX& y, ConstraintTerms& out) {
  const Model& model = system_.model();
  Data& data = system_.mutable_data();
  system_.compute_kinematics(y);
  out.mass = mass_matrix(model, data);
  const int m = model.num_constraint_rows;
  out.jacobian.resize(m, model.nv);
  out.residual.resize(m);
  out.velocity_target.resize(m);
  out.bias.resize(m);
  if (m == 0) return;
  constraint_jacobian(model, data, t, out.jacobian);
  constraint_residual(model, data, system_.configuration(), t, out.residual);
  constraint_velocity_target(model, data, t, out.velocity_target);
  constraint_bias(model, data, t, out.bias);
}

void Index3Form::constraint_bias_at(double t, const VectorX& y, VectorX& gamma) {
  const Model& model = system_.model();
  system_.compute_kinematics(y);
  gamma.resize(model.num_constraint_rows);
  if (model.has_constraints()) constraint_bias(model, system_.mutable_data(), t, gamma);
}

}  // namespace heavesim
