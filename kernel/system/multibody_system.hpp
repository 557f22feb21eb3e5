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
#include <memory>
#include <vector>

#include "kernel/algorithms/constrained_dynamics.hpp"
#include "kernel/system/dae_system.hpp"
#include "kernel/system/force_element.hpp"

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

class MultibodySystem : public OdeSystem, public DaeSystem {
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
  [[noreturn]] void report_non_finite(double t) const;
  void element_state_derivatives(double t, const VectorX& y, const Data& data, Eigen::Ref<VectorX> zdot) const;
  // DAE helpers (multibody_dae.cpp)
  void configuration_maps();                 // dae_N_ and dae_N_plus_ at q_
  void generalized_applied_force(const Data& base, const AppliedForces& forces, VectorX& out);
  bool has_applied_state_dependence() const;
  /// Constraint rows in the DAE: the independent ones at the initial state.
  int dae_rows() const { return static_cast<int>(dae_rows_.size()); }

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
  VectorX dae_w_, dae_qdot_, dae_qdot_plus_, dae_applied_, dae_applied_plus_, dae_zdot_, dae_zdot_plus_;
  VectorX dae_q_plus_, dae_vdot_;
  AlignedVector<Force> dae_subtree_forces_;
  MatrixX dae_N_, dae_N_plus_;
  std::vector<int> dae_rows_;  // constraint rows kept in the DAE (set by dae_initial_values)
  MatrixX dae_jacobian_, dae_jacobian_plus_;  // J of the kept rows; finite-difference column workspace
  VectorX dae_constraint_;                    // Phi of the kept rows
};

}  // namespace heavesim
