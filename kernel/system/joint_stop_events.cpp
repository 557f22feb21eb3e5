#include "kernel/system/joint_stop_events.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <Eigen/Cholesky>

#include "kernel/algorithms/constraint_equations.hpp"
#include "kernel/algorithms/kinematics.hpp"
#include "kernel/algorithms/mass_matrix.hpp"
#include "kernel/algorithms/projection.hpp"

namespace heavesim {

namespace {

/// A gap this small [m or rad] is a stop touching its bound: IDA places an event to
/// about 100 unit round-offs of t, and the state there is interpolated.
double touching_gap(const JointStopConstraint& stop) { return 1e-9 * std::max(1.0, std::abs(stop.bound)); }

}  // namespace

JointStopEvents::JointStopEvents(MultibodySystem& system, JointStopEventOptions options)
    : system_(system), options_(options) {
  const Model& model = system.model();
  for (const Constraint& constraint : model.constraints)
    if (const auto* stop = std::get_if<JointStopConstraint>(&constraint.kind)) {
      rows_.push_back(constraint.first_row);
      stops_.push_back(stop);
    }
  impulses_ = VectorX::Zero(count());
  workspace_ = ComplementarityWorkspace(model.num_constraint_rows);
}

double JointStopEvents::gap(int e, const VectorX& q) const {
  const JointStopConstraint& stop = *stops_[e];
  return stop.side * (q[system_.model().joints[stop.joint].q_index] - stop.bound);
}

double JointStopEvents::event_gap(int e, const VectorX& q) const {
  // A stop that lets go leaves with no speed, and IDA brackets the force's zero only to
  // its root tolerance: on the early side the force still presses and the coordinate dips
  // a round-off (1e-25 m) into the stop before it leaves. An impact is an event only
  // beyond that: 1e-12 of the bound's scale; the handler puts the coordinate back on it.
  return gap(e, q) + 1e-12 * std::max(1.0, std::abs(stops_[e]->bound));
}

void JointStopEvents::start(double t, VectorX& state) {
  const Model& model = system_.model();
  Data& data = system_.mutable_data();
  std::vector<int> candidates;
  for (int e = 0; e < count(); ++e) {
    data.constraint_active[rows_[e]] = 0.0;
    const JointStopConstraint& stop = *stops_[e];
    const Joint& joint = model.joints[stop.joint];
    // At its bound (or within the tolerance beyond it that the case allows) and not
    // moving away: it may carry load from the start.
    if (gap(e, state.head(model.nq)) <= touching_gap(stop) && stop.side * state[model.nq + joint.v_index] <= 0.0) {
      state[joint.q_index] = stop.bound;
      state[model.nq + joint.v_index] = 0.0;
      candidates.push_back(e);
    }
  }
  settle_active_set(t, state, candidates);
}

void JointStopEvents::handle(double t, VectorX& state, const std::vector<int>& found) {
  const Model& model = system_.model();
  Data& data = system_.mutable_data();
  bool closing = false;
  for (int e = 0; e < count(); ++e) {
    if (!found[e]) continue;
    if (active(e))
      data.constraint_active[rows_[e]] = 0.0;  // its force turned to a pull: it lets go
    else
      closing = true;
  }
  if (!closing) return;
  // Every stop at its bound takes part in the impact: the one that closed, the active
  // ones, and free ones that touch.
  std::vector<int> closed;
  for (int e = 0; e < count(); ++e)
    if (active(e) || found[e] || gap(e, state.head(model.nq)) <= touching_gap(*stops_[e])) closed.push_back(e);
  for (const int e : closed) {
    const JointStopConstraint& stop = *stops_[e];
    state[model.joints[stop.joint].q_index] = stop.bound;  // on the bound, not a round-off beyond it
  }
  impact(t, state, closed);
  // Those left at rest on their bound (a plastic impact) may carry load from now on;
  // the others bounced away.
  std::vector<int> resting;
  for (const int e : closed) {
    const JointStopConstraint& stop = *stops_[e];
    const double separation = stop.side * state[model.nq + model.joints[stop.joint].v_index];
    data.constraint_active[rows_[e]] = 0.0;
    if (separation <= 1e-6 * options_.restitution_threshold) {
      state[model.nq + model.joints[stop.joint].v_index] = 0.0;
      resting.push_back(e);
    }
  }
  settle_active_set(t, state, resting);
}

void JointStopEvents::impact(double t, VectorX& state, const std::vector<int>& closed) {
  const Model& model = system_.model();
  Data& data = system_.mutable_data();
  const int nq = model.nq, nv = model.nv;
  for (const int e : closed) data.constraint_active[rows_[e]] = 1.0;
  system_.compute_kinematics(state);
  constraint_jacobian(model, data, t, data.constraint_jacobian);
  constraint_velocity_target(model, data, t, data.constraint_velocity_target);
  // The rows of the impact: every bilateral row (loops and drivers transmit impulses),
  // then the stops at their bounds.
  std::vector<int> rows;
  for (const Constraint& constraint : model.constraints)
    if (!constraint.is_unilateral())
      for (int k = 0; k < static_cast<int>(constraint.rows.size()); ++k) rows.push_back(constraint.first_row + k);
  const int bilateral = static_cast<int>(rows.size());
  for (const int e : closed) rows.push_back(rows_[e]);
  const int m = static_cast<int>(rows.size());
  const MatrixX J = data.constraint_jacobian(rows, Eigen::all);
  const Eigen::LLT<MatrixX> mass(mass_matrix(model, data));
  const MatrixX minv_jt = mass.solve(J.transpose());
  MatrixX A = J * minv_jt;
  const VectorX v_before = state.segment(nq, nv);
  VectorX offset = J * v_before - data.constraint_velocity_target(rows);
  VectorX lower = VectorX::Zero(m), upper = VectorX::Constant(m, std::numeric_limits<double>::infinity());
  lower.head(bilateral).setConstant(-std::numeric_limits<double>::infinity());
  for (int k = bilateral; k < m; ++k) {
    const JointStopConstraint& stop = *stops_[closed[k - bilateral]];
    const double approach = offset[k];  // side v_j before: < 0 closing
    // Newton's law: side v+ >= -e side v-, for impacts faster than the threshold.
    if (approach < -options_.restitution_threshold) offset[k] += stop.restitution * approach;
  }
  // Redundant rows (a stop on a joint a loop already fixes) make A singular: eps I with
  // the proximal-point iteration, as in the contact step (contact_stepper.cpp).
  const double eps = 1e-10 * (m > 0 ? A.diagonal().mean() : 0.0);
  A.diagonal().array() += eps;
  VectorX impulse = VectorX::Zero(m), centre = VectorX::Zero(m);
  const ComplementarityProblem problem{A, offset, lower, upper};
  FallbackChainOptions chain;
  chain.order = {ComplementaritySolver::dantzig, ComplementaritySolver::projected_gauss_seidel,
                 ComplementaritySolver::lemke};
  for (int solve = 0; solve < 3; ++solve) {
    offset -= eps * centre;
    const ComplementarityResult result = solve_complementarity(problem, workspace_, impulse, chain);
    offset += eps * centre;
    if (!result.solved()) {
      std::ostringstream what;
      what << "the impact of the joint stops at t = " << t << " s found no impulses (" << m << " rows: " << bilateral
           << " constraint rows and the stops";
      for (const int e : closed)
        what << " '" << constraint_of_row(model, rows_[e])->name << "'";
      what << "): " << (result.message.empty() ? std::string(to_string(result.status)) : result.message);
      throw NumericalError(t, what.str(),
                           "check that no driver pushes a joint into its stop (a prescribed motion cannot be "
                           "stopped), and that two stops do not hold one coordinate from both sides");
    }
    centre = impulse;
  }
  state.segment(nq, nv) = v_before + minv_jt * impulse;
  impulses_.setZero();
  for (int k = bilateral; k < m; ++k) {
    const int e = closed[k - bilateral];
    impulses_[e] = impulse[k];
    if (ContactForces* contacts = system_.contacts()) contacts->add_stop_row_impulse(rows_[e], stops_[e]->side * impulse[k]);
  }
}

void JointStopEvents::settle_active_set(double t, const VectorX& state, std::vector<int> candidates) {
  Data& data = system_.mutable_data();
  for (const int e : candidates) data.constraint_active[rows_[e]] = 1.0;
  VectorX rate(state.size());
  while (!candidates.empty()) {
    system_.state_derivative(t, state, rate);  // the multipliers of the active rows
    const VectorX& lambda = data.constraint_multipliers;
    const double scale = lambda.cwiseAbs().maxCoeff();
    auto pulling = candidates.end();
    double hardest = -1e-9 * scale;
    for (auto it = candidates.begin(); it != candidates.end(); ++it)
      if (lambda[rows_[*it]] < hardest) hardest = lambda[rows_[*it]], pulling = it;
    if (pulling == candidates.end()) return;
    data.constraint_active[rows_[*pulling]] = 0.0;
    candidates.erase(pulling);
  }
}

}  // namespace heavesim
