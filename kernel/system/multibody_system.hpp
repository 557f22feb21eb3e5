#pragma once
// A multibody model with its force elements and constraints, as the two systems the
// integrators know:
//
// OdeSystem (explicit methods): y = [q (nq); v (nv); z_1; ...; z_k] with
//   dq/dt = N(q) v,  dv/dt = qdd (ABA for trees; the constrained KKT solve with loops),
//   dz_e/dt = g_e(t, q, v, z_e); after each step project() renormalizes quaternions and
//   moves (q, v) back onto Phi = 0, J v = 0.
// DaeSystem (IDA): the stabilized index-2 (Gear-Gupta-Leimkuhler) form, see
//   multibody_dae.cpp; y_dae = [q; v; z; lambda (m); mu (m)].
// SecondOrderSystem (index-3 HHT): the equations of motion with every constraint row,
//   see second_order_form.cpp and dynamics_derivatives.cpp.
#include <memory>
#include <vector>

#include "kernel/algorithms/constrained_dynamics.hpp"
#include "kernel/system/dae_system.hpp"
#include "kernel/elements/force_element.hpp"
#include "kernel/system/second_order_system.hpp"

namespace heavesim {

struct SystemSettings {
  ForwardDynamicsMethod method = ForwardDynamicsMethod::articulated_body;  // trees without loops
  double projection_tolerance = 1e-10;    // max |Phi| after a projection [m or rad]
  int projection_iterations = 8;
  /// Largest |J qdd - gamma| relative to |gamma| + |J M^-1 (tau - C)| accepted from the
  /// KKT solve; above it the constraint equations have no solution (a singular
  /// configuration) and the run stops with a diagnosis.
  double kkt_consistency_tolerance = 1e-6;
};

class MultibodySystem : public OdeSystem, public DaeSystem, public SecondOrderSystem {
 public:
  explicit MultibodySystem(std::shared_ptr<const Model> model, SystemSettings settings = {});

  void add_force_element(std::unique_ptr<ForceElement> element);

  // --- OdeSystem ---
  int size() const override { return size_; }
  void derivative(double t, const VectorX& y, VectorX& ydot) override;
  void project(double t, VectorX& y) override;

  // --- DaeSystem (multibody_dae.cpp) ---
  int dae_size() const override { return size_ + 2 * dae_rows(); }
  void differential_mask(VectorX& mask) const override;
  void dae_initial_values(double t, const VectorX& state, VectorX& y, VectorX& yp) override;
  void state_from_dae(const VectorX& y, VectorX& state) const override { state = y.head(size_); }
  void residual(double t, const VectorX& y, const VectorX& yp, VectorX& r) override;
  bool jacobian(double t, const VectorX& y, const VectorX& yp, double cj, MatrixX& J) override;

  // --- SecondOrderSystem (second_order_form.cpp) ---
  int configuration_size() const override { return model_->nq; }
  int velocity_size() const override { return model_->nv; }
  int constraint_size() const override { return model_->num_constraint_rows; }
  int element_state_size() const override { return size_ - model_->nq - model_->nv; }
  void integrate_configuration(const VectorX& q, const VectorX& step, VectorX& q_out) const override;
  void initial_accelerations(double t, const VectorX& y, VectorX& a, VectorX& zdot, VectorX& lambda) override;
  void dynamics_residual(double t, const VectorX& y, const VectorX& a, const VectorX& zdot, double penalty,
                         VectorX& lambda, Eigen::Ref<VectorX> r_v, Eigen::Ref<VectorX> r_z,
                         Eigen::Ref<VectorX> phi) override;
  void dynamics_derivatives(double t, const VectorX& y, const VectorX& a, DynamicsDerivatives& out) override;
  void constraint_terms(double t, const VectorX& y, ConstraintTerms& out) override;
  void constraint_bias_at(double t, const VectorX& y, VectorX& gamma) override;

  /// Evaluates the full pipeline at (t, y) for outputs: stages, forces, qdd, constraint
  /// multipliers and, when asked, the joint wrenches (loop forces included).
  void evaluate(double t, const VectorX& y, bool compute_reactions);

  /// Initial state: q0, v0 and every element's initial internal state.
  VectorX initial_state(const VectorX& q0, const VectorX& v0) const;

  const Model& model() const { return *model_; }
  const Data& data() const { return data_; }
  Data& mutable_data() { return data_; }
  const SystemSettings& settings() const { return settings_; }
  const AppliedForces& applied_forces() const { return forces_; }
  /// Applied external forces plus constraint wrenches, per link (after evaluate()).
  const AlignedVector<Force>& total_external_forces() const { return total_loads_; }
  const std::vector<std::unique_ptr<ForceElement>>& force_elements() const { return elements_; }
  /// Offset of element e's internal states in y.
  int state_offset(std::size_t element) const { return state_offsets_[element]; }
  const VectorX& configuration() const { return q_; }
  const VectorX& velocity() const { return v_; }

 private:
  /// Stages and applied forces at (t, q_, v_) for internal states z in y.
  void compute_stages_and_forces(double t, const VectorX& y);
  /// Stages, applied forces and qdd (with lambda for loops) at (t, y).
  void compute_accelerations(double t, const VectorX& y);
  void check_constraint_solution(double t);
  /// Names the first joint whose entry of per_coordinate (nv) is not finite.
  [[noreturn]] void report_non_finite(double t, const VectorX& per_coordinate, const std::string& what) const;
  void element_state_derivatives(double t, const VectorX& y, const Data& data, Eigen::Ref<VectorX> zdot) const;
  // DAE helpers (multibody_dae.cpp)
  void configuration_maps();                 // dae_N_ and dae_N_plus_ at q_
  /// Constraint rows in the DAE: the independent ones at the initial state.
  int dae_rows() const { return static_cast<int>(dae_rows_.size()); }
  // Derivatives (dynamics_derivatives.cpp)
  /// The GGL form's extra terms: d(J^T mu)/d(tangent q) and d(J v)/d(tangent q).
  struct GglDerivatives {
    VectorX mu;
    MatrixX jt_mu_q, jv_q;
  };
  /// Partial derivatives at (t, y, a) with multipliers lambda on constraint rows `rows`;
  /// leaves the stages and forces at (t, y) and J of those rows in rows_jacobian_.
  void differentiate_dynamics(double t, const VectorX& y, const VectorX& a, const std::vector<int>& rows,
                              const VectorX& lambda, DynamicsDerivatives& out, GglDerivatives* ggl);
  /// Q = tau + sum_i J_i^T f_i of `forces`, mapped with the subspaces in `base`.
  void generalized_applied_force(const Data& base, const AppliedForces& forces, VectorX& out);
  /// Joint and element forces at (t, q, v, y's element states) on `stages`, into scratch_forces_.
  void applied_forces_at(double t, const Data& stages, const VectorX& q, const VectorX& v, const VectorX& y);
  bool has_applied_state_dependence() const;

  std::shared_ptr<const Model> model_;
  SystemSettings settings_;
  Data data_;
  Data scratch_data_;  // finite-difference Jacobian columns (multibody_dae.cpp)
  AppliedForces forces_;
  AppliedForces scratch_forces_;
  AlignedVector<Force> total_loads_;
  std::vector<std::unique_ptr<ForceElement>> elements_;
  std::vector<int> state_offsets_;
  int size_;
  VectorX q_, v_, tau_total_, kkt_mismatch_;
  // DAE workspaces (multibody_dae.cpp)
  VectorX dae_w_, dae_qdot_, dae_qdot_plus_, dae_zdot_, dae_vdot_, dae_lambda_;
  MatrixX dae_N_, dae_N_plus_;
  std::vector<int> dae_rows_;  // constraint rows kept in the DAE (set by dae_initial_values)
  VectorX dae_constraint_;     // Phi of the kept rows
  DynamicsDerivatives derivatives_;
  GglDerivatives ggl_derivatives_;
  // Derivative workspaces (dynamics_derivatives.cpp)
  MatrixX rows_jacobian_, jacobian_change_;  // J of the rows in use; dJ/d(tangent k)
  AlignedVector<Force> subtree_forces_;
  VectorX applied_base_, applied_perturbed_, rates_base_, rates_perturbed_, direction_;
  VectorX q_perturbed_, v_perturbed_, y_perturbed_;
  // Second-order form (second_order_form.cpp)
  VectorX initial_rate_, multiplier_force_;
};

}  // namespace heavesim
