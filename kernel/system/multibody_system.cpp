#include "kernel/system/multibody_system.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <variant>

#include <Eigen/SVD>

#include "kernel/algorithms/configuration.hpp"
#include "kernel/parameter_error.hpp"
#include "kernel/algorithms/constraint_equations.hpp"
#include "kernel/algorithms/joint_forces.hpp"
#include "kernel/algorithms/inverse_dynamics.hpp"
#include "kernel/algorithms/joint_reactions.hpp"
#include "kernel/algorithms/mass_matrix.hpp"
#include "kernel/algorithms/projection.hpp"

namespace heavesim {

MultibodySystem::MultibodySystem(std::shared_ptr<const Model> model, SystemSettings settings)
    : model_(std::move(model)),
      settings_(settings),
      data_(*model_),
      forces_(*model_),
      total_loads_(model_->num_links(), Force::Zero()),
      size_(model_->nq + model_->nv),
      q_(VectorX::Zero(model_->nq)),
      v_(VectorX::Zero(model_->nv)),
      tau_total_(VectorX::Zero(model_->nv)),
      constraint_force_(VectorX::Zero(model_->nv)),
      kkt_mismatch_(VectorX::Zero(model_->num_constraint_rows)),
      dynamic_residual_(VectorX::Zero(model_->nv)) {
  bool joint_elements = false;
  for (int i = 1; i < model_->num_links(); ++i) joint_elements |= model_->joints[i].spring || model_->joints[i].limits;
  applied_dependencies_ = {false, joint_elements, joint_elements, false, false};
  // Every evaluation of a CRBA system, or of one with loops, forms M and its factor (an
  // ABA system without loops never has them).
  if (settings_.method == ForwardDynamicsMethod::composite_rigid_body || model_->has_constraints())
    size_mass_matrix(*model_, data_);
}

void MultibodySystem::add_force_element(std::unique_ptr<ForceElement> element) {
  state_offsets_.push_back(size_);
  size_ += element->state_size();
  const ElementDependencies d = element->dependencies();
  applied_dependencies_.time |= d.time;
  applied_dependencies_.configuration |= d.configuration;
  applied_dependencies_.velocity |= d.velocity;
  applied_dependencies_.element_states |= d.element_states && element->state_size() > 0;
  applied_dependencies_.history |= d.history;
  elements_.push_back(std::move(element));
}

void MultibodySystem::set_contacts(std::unique_ptr<ContactForces> contacts) {
  if (contacts_) throw ParameterError("contacts", "a second contact set", "one per system");
  contacts_ = contacts.get();
  add_force_element(std::move(contacts));
}

VectorX MultibodySystem::initial_state(const VectorX& q0, const VectorX& v0) const {
  VectorX y(size_);
  y << q0, v0, VectorX::Zero(size_ - model_->nq - model_->nv);
  for (std::size_t e = 0; e < elements_.size(); ++e)
    elements_[e]->initial_state(y.segment(state_offsets_[e], elements_[e]->state_size()));
  return y;
}

void MultibodySystem::compute_kinematics(const VectorX& y) {
  const Model& model = *model_;
  q_ = y.head(model.nq);
  v_ = y.segment(model.nq, model.nv);
  // The state the stages already hold (a kinematic analysis evaluates the loads at the
  // point it has just solved): the position-level work (transforms, M's factor) stands.
  constexpr unsigned held = StageMarker::positions | StageMarker::velocities;
  if ((data_.stages.current & held) == held && data_.q == q_ && data_.v == v_) {
    data_.stages.same_state_again();
    return;
  }
  update_positions(model, data_, q_);
  update_velocities(model, data_, q_, v_);
}

void MultibodySystem::compute_stages_and_forces(double t, const VectorX& y) {
  const Model& model = *model_;
  compute_kinematics(y);
  data_.stages.time = t;
  forces_.clear();
  add_joint_element_forces(model, q_, v_, forces_.joint_force);
  for (std::size_t e = 0; e < elements_.size(); ++e)
    elements_[e]->apply(t, model, data_, y.segment(state_offsets_[e], elements_[e]->state_size()), forces_);
}

void MultibodySystem::applied_forces_at(double t, const Data& stages, const VectorX& q, const VectorX& v,
                                        const VectorX& y, AppliedForces& forces) const {
  const Model& model = *model_;
  forces.clear();
  add_joint_element_forces(model, q, v, forces.joint_force);
  for (std::size_t e = 0; e < elements_.size(); ++e)
    elements_[e]->apply(t, model, stages, y.segment(state_offsets_[e], elements_[e]->state_size()), forces);
}

void MultibodySystem::compute_accelerations(double t, const VectorX& y) {
  const Model& model = *model_;
  compute_stages_and_forces(t, y);
  if (model.has_constraints()) {
    constrained_forward_dynamics(model, data_, t, forces_.joint_force, forces_.external_force_world);
    check_constraint_solution(t);
  } else {
    forward_dynamics(model, data_, forces_.joint_force, forces_.external_force_world, settings_.method);
  }
  if (!data_.qdd.allFinite()) report_non_finite(t, data_.qdd, "acceleration");
}

void MultibodySystem::check_constraint_solution(double t) {
  // The KKT solve returns a least-squares answer even when J qdd = gamma has no
  // solution; a residual beyond round-off means the configuration is singular.
  // (J M^-1 J^T) lambda - b is J qdd minus its target.
  const double scale = data_.kkt_rhs.cwiseAbs().maxCoeff() + data_.constraint_bias.cwiseAbs().maxCoeff() + 1e-300;
  VectorX& mismatch = kkt_mismatch_;
  mismatch.noalias() = data_.kkt_schur * data_.constraint_multipliers;
  mismatch -= data_.kkt_rhs;
  int worst = 0;
  const double error = mismatch.cwiseAbs().maxCoeff(&worst) / scale;
  if (error <= settings_.kkt_consistency_tolerance) return;
  // The error path may allocate. The rows becoming dependent say why: a driver among
  // them prescribes what the loop cannot follow, and then no integrator can go on.
  const ConstraintRank rank = analyse_constraint_rank(*model_, data_, t);
  const StateDiagnosis loss = constraint_loss(t, 1.0);
  std::string what = "the constraint equations have no solution (singular configuration): the acceleration of " +
                     describe_constraint_row(*model_, worst) + " cannot be met (relative mismatch " +
                     std::to_string(error) + ", rank " + std::to_string(rank.rank) + " of " +
                     std::to_string(model_->num_constraint_rows) + ")";
  throw loss.explain(t, what,
                     "the mechanism has reached a locked or singular position: check the loop geometry, "
                     "the initial state and the applied loads. A mechanism that passes through such a "
                     "position (a four-bar lying flat) is carried through by the index-3 integrator "
                     "(solver.integrator: hht); one that cannot move on (a loop stretched to its reach, a "
                     "dead centre) stops here with any integrator");
}

void MultibodySystem::spread_multipliers_over_every_row(double t) {
  // The constraint force f = J_used^T lambda is unique; the multipliers reported are the
  // minimum-norm ones over every row for it, whichever rows were set aside.
  constraint_force_.noalias() = data_.constraint_jacobian.transpose() * data_.constraint_multipliers;
  constraint_jacobian(*model_, data_, t, data_.constraint_jacobian);
  minimum_norm_multipliers(constraint_force_);
}

void MultibodySystem::minimum_norm_multipliers(const VectorX& generalized_force) {
  // lambda = S^+ J M^-1 f with S = J M^-1 J^T: the normal equations of min |J^T lambda - f|
  // in the metric M^-1. They satisfy S lambda = J M^-1 f, and S^+ S is the projection onto
  // range(J), so for f in the range of J^T these are the exact multipliers of the KKT
  // system (constrained_dynamics.hpp), minimum-norm over redundant rows.
  data_.kkt_minv_jt = data_.constraint_jacobian.transpose();
  data_.mass_matrix_cholesky.solveInPlace(data_.kkt_minv_jt);
  data_.kkt_schur.noalias() = data_.constraint_jacobian * data_.kkt_minv_jt;
  data_.kkt_rhs.noalias() = data_.kkt_minv_jt.transpose() * generalized_force;
  data_.kkt_solver.compute(data_.kkt_schur, kkt_regularization);
  data_.kkt_solver.solve(data_.kkt_rhs, data_.constraint_multipliers);
}

void MultibodySystem::compute_joint_reactions(double t) {
  // Without a constraint's loads, the articulated-body pass that gave the accelerations
  // holds every joint's wrench already (f = I^A a + p^A): no second pass. A recorded sample
  // of the drilling run spent ~10 % of its evaluation in that pass (docs/performance.md,
  // "Issue #18, nineteenth round").
  if (reactions_from_articulated_pass() && articulated_body_joint_wrenches(*model_, data_)) return;
  total_loads_ = forces_.external_force_world;
  if (model_->has_constraints()) {
    tau_total_ = forces_.joint_force;
    add_constraint_loads(*model_, data_, t, data_.constraint_multipliers, total_loads_, tau_total_);
  }
  compute_joint_wrenches(*model_, data_, total_loads_);
}

void MultibodySystem::element_state_derivatives(double t, const VectorX& y, const Data& data,
                                                Eigen::Ref<VectorX> zdot) const {
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    const int n = elements_[e]->state_size();
    if (n == 0) continue;
    const int offset = state_offsets_[e] - (model_->nq + model_->nv);
    elements_[e]->state_derivative(t, *model_, data, y.segment(state_offsets_[e], n), zdot.segment(offset, n));
  }
}

void MultibodySystem::state_derivative(double t, const VectorX& y, VectorX& ydot) {
  const Model& model = *model_;
  compute_accelerations(t, y);
  configuration_derivative(model, q_, v_, ydot.head(model.nq));
  ydot.segment(model.nq, model.nv) = data_.qdd;
  element_state_derivatives(t, y, data_, ydot.tail(size_ - model.nq - model.nv));
}

void MultibodySystem::evaluate(double t, const VectorX& y, bool compute_reactions) {
  compute_accelerations(t, y);
  if (!compute_reactions) return;
  if (data_.constraint_rows_set_aside) spread_multipliers_over_every_row(t);
  compute_joint_reactions(t);
}

void MultibodySystem::evaluate_prescribed(double t, const VectorX& y, const VectorX& qdd, bool compute_reactions) {
  const Model& model = *model_;
  compute_stages_and_forces(t, y);
  // f = M qdd + C - tau: RNEA with the applied external forces and gravity, less the
  // applied joint forces. Its accelerations are those of the motion: the stage is current.
  inverse_dynamics(model, data_, qdd, forces_.external_force_world);
  data_.qdd = qdd;
  data_.stages.accelerations_computed();
  dynamic_residual_ = data_.tau - forces_.joint_force;
  if (model.has_constraints()) {
    // The multipliers that best supply f = M qdd + C - tau (exact for a dynamically
    // consistent motion, f in the range of J^T); what remains is the dynamic residual.
    constraint_jacobian(model, data_, t, data_.constraint_jacobian);
    factorize_mass_matrix(model, data_);
    minimum_norm_multipliers(dynamic_residual_);
    dynamic_residual_.noalias() -= data_.constraint_jacobian.transpose() * data_.constraint_multipliers;
  }
  if (!data_.constraint_multipliers.allFinite()) report_non_finite(t, dynamic_residual_, "constraint force");
  if (compute_reactions) compute_joint_reactions(t);
}

std::string MultibodySystem::describe_state_component(int index) const {
  const Model& model = *model_;
  const bool speed = index >= model.nq && index < model.nq + model.nv;
  if (index < model.nq + model.nv) {
    const int coordinate = speed ? index - model.nq : index;
    for (int i = 1; i < model.num_links(); ++i) {
      const Joint& joint = model.joints[i];
      const int first = speed ? joint.v_index : joint.q_index, count = speed ? joint.nv : joint.nq;
      if (count == 0 || coordinate < first || coordinate >= first + count) continue;
      std::string what = speed ? "speed" : "coordinate";
      if (count > 1) what += " " + std::to_string(coordinate - first);
      return what + " of joint '" + joint.name + "' (body '" + model.links[i].name + "')";
    }
  }
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    const int offset = state_offsets_[e], n = elements_[e]->state_size();
    if (index >= offset && index < offset + n)
      return "state " + std::to_string(index - offset) + " of force element '" + elements_[e]->name() + "'";
  }
  return "state component " + std::to_string(index);
}

StateDiagnosis MultibodySystem::diagnose_state(double t, const VectorX& y) {
  const Model& model = *model_;
  for (int k = 0; k < y.size(); ++k)
    if (!std::isfinite(y[k])) return {"the " + describe_state_component(k) + " is not finite", ""};
  if (!model.has_constraints()) return {};
  compute_kinematics(y);
  // Away from a singular configuration the ratio is of order one (Bricard's mechanism:
  // ~0.3; the A02 four-bars: 1e-2 at 0.01 rad from lying flat).
  return constraint_loss(t, 1e-4);
}

StateDiagnosis MultibodySystem::constraint_loss(double t, double max_ratio) {
  const Model& model = *model_;
  if (!model.has_constraints()) return {};
  constraint_jacobian(model, data_, t, data_.constraint_jacobian);
  const Eigen::JacobiSVD<MatrixX> svd(data_.constraint_jacobian, Eigen::ComputeThinU);
  const VectorX& sigma = svd.singularValues();
  int rank = constraint_rank_;
  if (rank < 0) rank = static_cast<int>((sigma.array() > constraint_rank_threshold * sigma[0]).count());
  if (rank <= 0 || rank > sigma.size() || !(sigma[0] > 0.0)) return {};
  const double ratio = sigma[rank - 1] / sigma[0];
  // The rows along the direction being lost (a left singular vector): every row that
  // carries at least a fifth of its largest entry, by constraint.
  const VectorX lost = svd.matrixU().col(rank - 1).cwiseAbs();
  std::string rows, drivers;
  std::vector<const Constraint*> named;
  const double largest = lost.maxCoeff();
  for (int row = 0; row < lost.size(); ++row) {
    if (lost[row] < 0.2 * largest) continue;
    const Constraint* constraint = constraint_of_row(model, row);
    rows += (rows.empty() ? "" : ", ") + describe_constraint_row(model, row);
    if (!constraint || std::find(named.begin(), named.end(), constraint) != named.end()) continue;
    named.push_back(constraint);
    if (const auto* driver = std::get_if<DriverConstraint>(&constraint->kind))
      drivers += (drivers.empty() ? "driver '" : ", driver '") + constraint->name + "' (joint '" +
                 model.joints[driver->joint].name + "')";
    else if (constraint->is_driver())
      drivers += (drivers.empty() ? "" : ", ") + std::string(constraint->kind_name()) + " '" + constraint->name + "'";
  }
  const bool driven = !drivers.empty();
  if (!(max_ratio >= 1.0 || ratio < max_ratio || (driven && ratio < 100.0 * max_ratio))) return {};
  std::string loop;  // the other constraints that close the loop the drivers pull on
  for (const Constraint* constraint : named)
    if (!constraint->is_driver())
      loop += (loop.empty() ? "" : ", ") + std::string(constraint->kind_name()) + " '" + constraint->name + "'";
  char text[32];
  std::snprintf(text, sizeof text, "%.2g", ratio);
  const std::string rank_text = "the constraint Jacobian's rank-" + std::to_string(rank) + " singular value is " +
                                text + " of its largest, lost along " + rows;
  if (!driven) return {"the loops are at a singular configuration: " + rank_text, ""};
  const std::string pulled = loop.empty() ? "the other constraints" : "the loop closed by " + loop;
  return {drivers + " pulls " + pulled + " where it cannot close (" + rank_text + ")",
          "the driver prescribes a motion the loop cannot follow (beyond its reach, or into a dead centre): change " +
              drivers + ": its position expression or its range, or the loop's geometry (lengths, attachment "
              "points); neither a smaller step nor another integrator carries a driven loop past this point"};
}

void MultibodySystem::report_non_finite(double t, const VectorX& per_coordinate, const std::string& what) const {
  const Model& model = *model_;
  for (int i = 1; i < model.num_links(); ++i) {
    const Joint& joint = model.joints[i];
    if (joint.nv > 0 && !per_coordinate.segment(joint.v_index, joint.nv).allFinite())
      throw NumericalError(t,
                           what + " of joint '" + joint.name + "' (body '" + model.links[i].name + "') is not finite",
                           "check that body's mass and inertia and the forces acting on it; a stiff or "
                           "unstable force element can also produce this");
  }
  throw NumericalError(t, what + " is not finite (a force element's state)",
                       "check the force elements' parameters and initial states");
}

}  // namespace heavesim
