#pragma once
// A multibody model with its force elements and constraints: the core that the
// integrators' forms (ode_form.hpp, ggl_dae_form.hpp, index3_form.hpp) evaluate, as in
// Simbody's System / State / Integrator separation. It holds the model, one Data, the
// force elements and the layout of the state
//   y = [q (nq); v (nv); z_1; ...; z_k]      (z_e: element e's internal states)
// and evaluates the equations of motion at (t, y):
//   dq/dt = N(q) v,  dv/dt = qdd (ABA for trees; the constrained KKT solve with loops),
//   dz_e/dt = g_e(t, q, v, z_e).
// The forms keep their own workspaces; the core's Data holds the stages of the last
// evaluation, which is what the recorder reads after evaluate().
#include <memory>
#include <string>
#include <vector>

#include "kernel/algorithms/constrained_dynamics.hpp"
#include "kernel/contact/contact_forces.hpp"
#include "kernel/elements/force_element.hpp"
#include "kernel/math/numerical_error.hpp"
#include "kernel/system/failure_diagnosis.hpp"

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

class MultibodySystem {
 public:
  explicit MultibodySystem(std::shared_ptr<const Model> model, SystemSettings settings = {});
  MultibodySystem(const MultibodySystem&) = delete;
  MultibodySystem& operator=(const MultibodySystem&) = delete;

  void add_force_element(std::unique_ptr<ForceElement> element);
  /// Adds the contacts (shapes, pairs, stops) as their force element, which the
  /// contact-stepping integrator fills with each step's contact loads; one per system.
  void set_contacts(std::unique_ptr<ContactForces> contacts);
  /// The contacts' element, null if the system has none.
  ContactForces* contacts() const { return contacts_; }

  /// Size of the state y = [q; v; z].
  int size() const { return size_; }
  /// nz, the number of element states.
  int element_state_size() const { return size_ - model_->nq - model_->nv; }

  /// Initial state: q0, v0 and every element's initial internal state.
  VectorX initial_state(const VectorX& q0, const VectorX& v0) const;

  /// Evaluates the full pipeline at (t, y) for outputs: stages, forces, qdd, constraint
  /// multipliers and, when asked, the joint wrenches (loop forces included).
  void evaluate(double t, const VectorX& y, bool compute_reactions);
  /// Whether evaluate() (a run's recorded sample) reads the joint reactions from the
  /// articulated-body pass that gave its accelerations (f = I^A a + p^A, Featherstone 2008,
  /// sec. 7.1: no second pass): a tree without constraint rows (no loop joint, coupler,
  /// distance or expression constraint, driver, nor joint stop under IDA) whose forward
  /// dynamics is ABA. Otherwise an inverse-dynamics pass with the constraint loads gives
  /// them; evaluate_prescribed() (kinematic analysis) always takes that pass.
  bool reactions_from_articulated_pass() const {
    return !model_->has_constraints() && settings_.method == ForwardDynamicsMethod::articulated_body;
  }

  /// Inverse dynamics along a prescribed motion (kinematic analysis, no integration):
  /// stages and applied forces at (t, y = [q; v; z]) with the accelerations `qdd` (nv)
  /// given, and the multipliers that best explain them,
  ///   J^T lambda = M qdd + C - tau   (tau: applied joint, gravity and external forces),
  /// least squares in the metric M^-1 (lambda = (J M^-1 J^T)^+ J M^-1 (M qdd + C - tau),
  /// minimum-norm over redundant rows: the multipliers a dynamic run reports for the same
  /// motion). The generalized force the constraints cannot supply (nonzero only along
  /// directions no constraint or driver holds) is kept as dynamic_residual(). With
  /// `compute_reactions`, the joint wrenches too.
  void evaluate_prescribed(double t, const VectorX& y, const VectorX& qdd, bool compute_reactions);
  /// M qdd + C - tau - J^T lambda (nv; N or N m) of the last evaluate_prescribed.
  const VectorX& dynamic_residual() const { return dynamic_residual_; }

  // --- evaluation stages, used by the forms ---
  /// ydot = f(t, y) of the ODE above (leaves every stage, the forces and qdd at (t, y)).
  void state_derivative(double t, const VectorX& y, VectorX& ydot);
  /// (q, v) from y, then the position and velocity stages.
  void compute_kinematics(const VectorX& y);
  /// compute_kinematics, then the joint-element and force-element loads at (t, y).
  void compute_stages_and_forces(double t, const VectorX& y);
  /// Stages, applied forces and qdd (with lambda for loops) at (t, y).
  void compute_accelerations(double t, const VectorX& y);
  /// Joint and element forces at (t, q, v, y's element states) on `stages`, into `forces`.
  void applied_forces_at(double t, const Data& stages, const VectorX& q, const VectorX& v, const VectorX& y,
                         AppliedForces& forces) const;
  /// dz/dt of every element at (t, y) on the stages in `data`.
  void element_state_derivatives(double t, const VectorX& y, const Data& data, Eigen::Ref<VectorX> zdot) const;
  /// What the applied forces and element-state rates depend on, over every element and
  /// the joint elements (springs, limits: q and v).
  const ElementDependencies& applied_dependencies() const { return applied_dependencies_; }
  /// Whether the applied forces depend on the state (q, v or z) at all.
  bool has_applied_state_dependence() const {
    return applied_dependencies_.configuration || applied_dependencies_.velocity || applied_dependencies_.element_states;
  }
  // --- diagnosis of a failed step (error path: may allocate) ---
  /// Names component `index` of y = [q; v; z]: "speed of joint 'pivot0' (body 'crank0')".
  std::string describe_state_component(int index) const;
  /// What stands out at (t, y): a non-finite component, or loops at (or, with a driver
  /// in the direction being lost, near) a singular configuration (constraint_loss);
  /// empty otherwise. Recomputes the position stage at y.
  StateDiagnosis diagnose_state(double t, const VectorX& y);
  /// The constraint rows that are becoming dependent at the current position stage: the
  /// rank-th singular value of J relative to its largest, the rows along the direction
  /// being lost, and whether a driver is among them (a driver that pulls a loop beyond
  /// its reach or into a dead centre: no integrator can go on). Reported when that ratio
  /// is below `max_ratio`, or below 100 max_ratio with a driver among the rows (a driven
  /// loop fails before it reaches the singular point: its speeds grow as 1/sqrt of the
  /// distance); max_ratio >= 1 always reports.
  StateDiagnosis constraint_loss(double t, double max_ratio);
  /// The rank of the constraint Jacobian on the manifold, as a form found it when it
  /// started (the reference for diagnose_state); -1 until then.
  void remember_constraint_rank(int rank) { constraint_rank_ = rank; }
  /// Names the first joint whose entry of per_coordinate (nv) is not finite.
  [[noreturn]] void report_non_finite(double t, const VectorX& per_coordinate, const std::string& what) const;

  const Model& model() const { return *model_; }
  const Data& data() const { return data_; }
  Data& mutable_data() { return data_; }
  const SystemSettings& settings() const { return settings_; }
  const AppliedForces& applied_forces() const { return forces_; }
  const std::vector<std::unique_ptr<ForceElement>>& force_elements() const { return elements_; }
  /// Offset of element e's internal states in y.
  int state_offset(std::size_t element) const { return state_offsets_[element]; }
  /// q and v of the last evaluation.
  const VectorX& configuration() const { return q_; }
  const VectorX& velocity() const { return v_; }

 private:
  void check_constraint_solution(double t);
  /// With rows set aside (Data::constraint_row_used), the minimum-norm multipliers over
  /// every row for the same constraint force, for reporting.
  void spread_multipliers_over_every_row(double t);
  /// The minimum-norm multipliers (in the metric M^-1) whose force J^T lambda best equals
  /// `generalized_force` (nv), from data_.constraint_jacobian (every row) and the current
  /// factor of M; into data_.constraint_multipliers.
  void minimum_norm_multipliers(const VectorX& generalized_force);
  /// Joint wrenches from the applied forces and the constraint loads of the multipliers.
  void compute_joint_reactions(double t);

  std::shared_ptr<const Model> model_;
  SystemSettings settings_;
  Data data_;
  AppliedForces forces_;
  AlignedVector<Force> total_loads_;
  std::vector<std::unique_ptr<ForceElement>> elements_;
  std::vector<int> state_offsets_;
  ElementDependencies applied_dependencies_;
  int size_;
  int constraint_rank_ = -1;
  ContactForces* contacts_ = nullptr;  // owned by elements_
  VectorX q_, v_, tau_total_, constraint_force_, kkt_mismatch_, dynamic_residual_;
};

}  // namespace heavesim
