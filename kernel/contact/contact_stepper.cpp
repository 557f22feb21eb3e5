#include "kernel/contact/contact_stepper.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <limits>

#include "kernel/algorithms/configuration.hpp"
#include "kernel/algorithms/constraint_equations.hpp"
#include "kernel/algorithms/mass_matrix.hpp"
#include "kernel/algorithms/tree_factorization.hpp"
#include "kernel/parameter_error.hpp"

namespace heavesim {

FallbackChainOptions ContactStepOptions::default_solvers() {
  FallbackChainOptions chain;
  chain.order = {ComplementaritySolver::dantzig, ComplementaritySolver::projected_gauss_seidel,
                 ComplementaritySolver::lemke};
  chain.count = 3;
  chain.projected_gauss_seidel.warm_start = true;
  chain.projected_gauss_seidel.max_iterations = 500;
  return chain;
}

ContactStepper::ContactStepper(const Model& model, ContactModel contacts, int max_contacts, ContactStepOptions options)
    : model_(model), contacts_(std::move(contacts)), options_(options) {
  check_contact_model(model, contacts_);
  if (!(options_.stabilization >= 0.0 && options_.stabilization <= 1.0))
    throw ParameterError("stabilization", std::to_string(options_.stabilization), "a fraction 0..1");
  if (!(options_.regularization >= 0.0 && std::isfinite(options_.regularization)))
    throw ParameterError("regularization", std::to_string(options_.regularization), "a finite number >= 0");
  if (max_contacts < 0) throw ParameterError("max_contacts", std::to_string(max_contacts), "a count >= 0");
  const int stops = static_cast<int>(contacts_.joint_stops.size());
  const int lines = static_cast<int>(contacts_.lines.size());
  int rows_per_point = 1;
  for (const ContactPair& pair : contacts_.pairs)
    rows_per_point = std::max(rows_per_point, 1 + (pair.friction_coefficient > 0.0 ? pair.friction_directions : 0) +
                                                  (pair.torsional_friction > 0.0 ? 1 : 0));
  capacity_rows_ = model.num_constraint_rows + rows_per_point * max_contacts + stops + lines;
  const int nv = model.nv;
  points_.resize(max_contacts);
  for (int j = 1; j < static_cast<int>(model.joints.size()); ++j)
    if (std::holds_alternative<FreeJoint>(model.joints[j].type)) free_joints_.push_back(j);
  contact_first_row_.resize(max_contacts);
  friction_rows_.resize(max_contacts);
  spin_rows_.resize(max_contacts);
  stop_row_.assign(stops, -1);
  stop_sign_.assign(stops, 0.0);
  line_row_.assign(lines, -1);
  line_point_a_.assign(lines, Vector3::Zero());
  line_point_b_.assign(lines, Vector3::Zero());
  line_direction_.assign(lines, Vector3::UnitZ());
  zero_acceleration_ = VectorX::Zero(nv);
  free_velocity_.resize(nv);
  velocity_next_.resize(nv);
  configuration_next_.resize(model.nq);
  mass_factor_.resize(nv, nv);
  jacobian_.resize(capacity_rows_, nv);
  row_links_.resize(capacity_rows_);
  minv_jacobian_t_.resize(nv, capacity_rows_);
  delassus_.resize(capacity_rows_, capacity_rows_);
  offset_.resize(capacity_rows_);
  impulses_ = VectorX::Zero(capacity_rows_);
  previous_impulses_ = VectorX::Zero(capacity_rows_);
  friction_coefficient_.resize(capacity_rows_);
  lower_.resize(capacity_rows_);
  fixed_lower_.resize(capacity_rows_);
  fixed_upper_.resize(capacity_rows_);
  previous_normal_.resize(capacity_rows_);
  best_impulses_.resize(capacity_rows_);
  upper_ = VectorX::Constant(capacity_rows_, std::numeric_limits<double>::infinity());
  friction_normal_.resize(capacity_rows_);
  workspace_ = ComplementarityWorkspace(capacity_rows_);
  for (int k = 0; k < options_.solvers.count; ++k)
    chain_has_dantzig_ |= options_.solvers.order[k] == ComplementaritySolver::dantzig;
}

// Row `row` of J gains sign * d . v_link(p): the velocity of the point p fixed on `link`
// along d, over the joints from the link to the root. Column c of the world motion
// subspace is (omega_c; v_c) about the world origin, so the point moves with
// v_c + omega_c x p, and d . (omega_c x p) = (p x d) . omega_c.
void ContactStepper::add_point_row(int row, int link, const Vector3& point, const Vector3& direction, double sign,
                                   const Data& data) {
  const Vector3 moment_arm = point.cross(direction);
  for (int i = link; i > 0; i = model_.joints[i].parent) {
    const Joint& joint = model_.joints[i];
    for (int c = joint.v_index; c < joint.v_index + joint.nv; ++c) {
      const auto s = data.motion_subspace_world.col(c);
      jacobian_(row, c) += sign * (direction.dot(s.tail<3>()) + moment_arm.dot(s.head<3>()));
    }
  }
}

Vector3 ContactStepper::friction_direction(const ContactPoint& point, int d, int k) {
  if (k <= 2) return d == 0 ? point.tangent1_world : point.tangent2_world;
  // The k boxes add up to a 2k-gon whose face normals are perpendicular to the
  // directions: with one direction along tangent2 (odd k), tangent1 is a face normal.
  const double angle = M_PI * d / k + (k % 2 == 1 ? M_PI / 2 : 0.0);
  return std::cos(angle) * point.tangent1_world + std::sin(angle) * point.tangent2_world;
}

double ContactStepper::friction_box_scale(int k) {
  if (k == 1) return 1.0;  // a sliding point's one row: mu z_n against the slip
  // The support of the sum of k boxes |z_d| <= c along directions pi/k apart is
  // c sum_d |cos(phi - theta_d)|, between cot(pi/2k) at a face normal and
  // csc(pi/2k) at a corner: c = tan(pi/2k) puts the faces on the circle of radius 1.
  return k == 2 ? 1.0 : std::tan(M_PI / (2.0 * k));
}

// A point that slips at the step's start has one friction row, along its slip
// direction, boxed by mu z_n: Coulomb's law for sliding, mu z_n against the slip whatever
// its direction (the four-facet pyramid gives up to sqrt(2) mu z_n on a diagonal, and a
// spinning bit's torque would ripple with its angle), and no grip across the slip, so
// that a force across a sliding body turns its path. The direction is the start's
// (explicit; first order where the path curves); the magnitude is implicit, so a slip
// that stops within the step sticks. Points that stick (slip below the threshold) keep
// the supporting shape's axes and the whole polygon of the pair's directions.
void ContactStepper::classify_friction(const Data& data) {
  const auto point_velocity = [&](int link, const Vector3& p) {
    const Motion& v = data.velocity_world[link];
    return Vector3(v.linear() + v.angular().cross(p));
  };
  for (int k = 0; k < contact_count_; ++k) {
    ContactPoint& c = points_[k];
    const ContactPair& pair = contacts_.pairs[c.pair];
    spin_rows_[k] = pair.torsional_friction > 0.0 ? 1 : 0;
    friction_rows_[k] = pair.friction_coefficient > 0.0 ? pair.friction_directions : 0;
    if (friction_rows_[k] == 0) continue;
    const Vector3 relative = point_velocity(c.link_a, c.point_world) - point_velocity(c.link_b, c.point_world);
    const Vector3 slip = relative - relative.dot(c.normal_world) * c.normal_world;
    const double speed = slip.norm();
    if (!(speed > options_.sliding_speed_threshold)) continue;
    c.tangent1_world = slip / speed;
    c.tangent2_world = c.normal_world.cross(c.tangent1_world);
    friction_rows_[k] = 1;
  }
}

void ContactStepper::add_spin_row(int row, int link, const Vector3& axis, double sign, const Data& data) {
  for (int i = link; i > 0; i = model_.joints[i].parent) {
    const Joint& joint = model_.joints[i];
    for (int c = joint.v_index; c < joint.v_index + joint.nv; ++c)
      jacobian_(row, c) += sign * axis.dot(data.motion_subspace_world.col(c).head<3>());
  }
}

template <typename Visit>
void ContactStepper::for_each_row_column(int row, Visit&& visit) const {
  const auto [link_a, link_b] = row_links_[row];
  if (link_a < 0) {  // a constraint row: any column
    for (int c = 0; c < model_.nv; ++c) visit(c);
    return;
  }
  // The joints from link_a to the root, then those from link_b up to the first one that is
  // also an ancestor of link_a (i <= link_a < subtree_end(i): depth-first order), so that
  // a shared joint is visited once.
  for (int i = link_a; i > 0; i = model_.joints[i].parent)
    for (int c = model_.joints[i].v_index; c < model_.joints[i].v_index + model_.joints[i].nv; ++c) visit(c);
  for (int i = link_b; i > 0 && !(i <= link_a && link_a < model_.links[i].subtree_end); i = model_.joints[i].parent)
    for (int c = model_.joints[i].v_index; c < model_.joints[i].v_index + model_.joints[i].nv; ++c) visit(c);
}

ContactStepReport ContactStepper::step(Data& data, double t, double h, VectorX& q, VectorX& v, const VectorX& tau,
                                       ExternalForces external) {
  ContactStepReport report;
  report.solve.status = ComplementarityStatus::solved;  // until a problem says otherwise (no rows: nothing to solve)

  // Unconstrained velocity: v* = v + h M^-1 (tau - C), C from inverse dynamics at qdd = 0
  // (velocity products, gravity and the external wrenches).
  update_positions(model_, data, q);
  update_velocities(model_, data, q, v);
  const VectorX& bias = inverse_dynamics(model_, data, zero_acceleration_, external);
  free_velocity_ = tau - bias;
  // M = L^T L with the tree's sparsity (only ancestor pairs): the solves below, one per
  // contact row, then cost the coordinates' depths instead of nv^2 each.
  const MatrixX& M = mass_matrix(model_, data);
  for (int i = 0; i < model_.nv; ++i)
    for (int j = i; j >= 0; j = model_.velocity_coordinate_parent[j]) mass_factor_(i, j) = M(i, j);
  if (!factorize_tree(model_.velocity_coordinate_parent, mass_factor_)) {
    report.solve.status = ComplementarityStatus::singular_pivot;
    report.solve.message = "the joint-space inertia matrix is not positive definite (a body without mass?)";
    return report;
  }
  solve_tree(model_.velocity_coordinate_parent, mass_factor_, free_velocity_);
  free_velocity_ = v + h * free_velocity_;
  // A free joint's linear velocity is in its moving (child) axes, whose rate holds the
  // term -omega x v_linear (in C above). Stepping that term explicitly while the axes
  // turn by h omega makes an error of (h omega)^2 per step that grows with the time run
  // (a rolling ball gained 1e-3 of its speed in 0.3 s at h = 1e-4). Here the step is
  // taken for the velocity in the parent's axes instead, frozen at R_k: the term is added
  // back, the position moves along R_k v+ and the velocity is expressed in the new axes
  // after the step (below), so constant forces give exactly constant accelerations.
  for (const int j : free_joints_) {
    const int vi = model_.joints[j].v_index;
    free_velocity_.segment<3>(vi + 3) += h * v.segment<3>(vi).cross(v.segment<3>(vi + 3));
  }

  // Contact points and stop rows at this configuration.
  const int found = detect_contacts(model_, data, contacts_, points_);
  if (found > static_cast<int>(points_.size())) {
    report.solve.status = ComplementarityStatus::invalid_input;
    report.solve.message = "more contact points than the " + std::to_string(points_.size()) + " the stepper holds";
    report.rows = capacity_rows_ + 1;
    return report;
  }
  contact_count_ = found;
  classify_friction(data);
  const int bilateral = model_.num_constraint_rows;
  int rows = bilateral;
  for (int k = 0; k < found; ++k) rows += 1 + friction_rows_[k] + spin_rows_[k];
  int stop_rows = 0;
  for (size_t s = 0; s < contacts_.joint_stops.size(); ++s) {
    const JointStop& stop = contacts_.joint_stops[s];
    const double coordinate = q[model_.joints[stop.joint].q_index];
    stop_row_[s] = -1;
    stop_sign_[s] = 0.0;
    // A stop's row is in the problem when the coordinate is within the margin of a bound
    // or would pass it in this step at the unconstrained velocity (speculative: the row
    // lets the gap close exactly and never pulls, so an early row costs nothing).
    const double speed = free_velocity_[model_.joints[stop.joint].v_index];
    if (std::min(coordinate - stop.lower, coordinate - stop.lower + h * speed) < contacts_.margin) stop_sign_[s] = 1.0;
    else if (std::min(stop.upper - coordinate, stop.upper - coordinate - h * speed) < contacts_.margin)
      stop_sign_[s] = -1.0;
    if (stop_sign_[s] != 0.0) stop_row_[s] = rows + stop_rows++;
  }
  rows += stop_rows;
  // Tension lines: rows are decided below, once their Jacobian rows are known (up to one each).
  const int rows_before_lines = rows;
  rows += static_cast<int>(contacts_.lines.size());
  report.constraint_rows = bilateral;
  report.contacts = found;
  report.active_stops = stop_rows;

  // Sized for every line; the rows of lines that are slack are dropped below.
  auto J_all = jacobian_.topRows(rows);
  J_all.setZero();
  friction_coefficient_.head(rows).setZero();
  friction_normal_.head(rows).setConstant(-1);
  lower_.head(rows).setZero();
  auto& J = J_all;
  auto mu = friction_coefficient_.head(rows);
  auto normal_of = friction_normal_.head(rows);
  if (bilateral > 0) {
    // The model's constraints (loop joints, couplers, drivers) as free rows: J v+ makes
    // Phi(q_{k+1}, t_{k+1}) = Phi(q_k, t_{k+1}) + h J v+ = 0 to first order, so a joint
    // driver, linear in q, is followed exactly and a loop's drift is removed each step.
    constraint_jacobian(model_, data, t + h, data.constraint_jacobian);
    constraint_residual(model_, data, q, t + h, data.constraint_residual);
    J.topRows(bilateral) = data.constraint_jacobian;
    offset_.head(bilateral) = data.constraint_residual / h;
    lower_.head(bilateral).setConstant(-std::numeric_limits<double>::infinity());
    for (int r = 0; r < bilateral; ++r) row_links_[r] = {-1, -1};
  }
  // Gap terms: b_i = min(gap / h (closing allowed, > 0) or the stabilization of an overlap,
  //                      e u_approach for an impact reached within this step).
  auto gap_velocity = [&](double gap, double approach_velocity, double restitution) {
    double term = gap > 0.0 ? gap / h : options_.stabilization * gap / h;
    if (restitution > 0.0 && -approach_velocity > options_.restitution_threshold &&
        gap + h * approach_velocity < 0.0)
      term = std::min(term, restitution * approach_velocity);
    return term;
  };
  int row = bilateral;
  for (int k = 0; k < found; ++k) {
    const ContactPoint& c = points_[k];
    const ContactPair& pair = contacts_.pairs[c.pair];
    contact_first_row_[k] = row;
    const int directions = 1 + friction_rows_[k];
    for (int d = 0; d < directions; ++d) {
      const Vector3 axis = d == 0 ? c.normal_world : friction_direction(c, d - 1, friction_rows_[k]);
      add_point_row(row + d, c.link_a, c.point_world, axis, 1.0, data);
      add_point_row(row + d, c.link_b, c.point_world, axis, -1.0, data);
      row_links_[row + d] = {c.link_a, c.link_b};
    }
    offset_[row] = gap_velocity(c.gap, J.row(row).dot(v), pair.restitution);
    const double box = pair.friction_coefficient * friction_box_scale(friction_rows_[k]);
    for (int d = 1; d < directions; ++d) {
      offset_[row + d] = 0.0;
      normal_of[row + d] = row;
      mu[row + d] = box;
    }
    row += directions;
    if (spin_rows_[k]) {
      // Torsional friction: the relative spin about the normal, boxed by mu_t z_n (N m s).
      add_spin_row(row, c.link_a, c.normal_world, 1.0, data);
      add_spin_row(row, c.link_b, c.normal_world, -1.0, data);
      row_links_[row] = {c.link_a, c.link_b};
      offset_[row] = 0.0;
      normal_of[row] = contact_first_row_[k];
      mu[row] = pair.torsional_friction;
      ++row;
    }
  }
  for (size_t s = 0; s < contacts_.joint_stops.size(); ++s) {
    if (stop_row_[s] < 0) continue;
    const JointStop& stop = contacts_.joint_stops[s];
    const Joint& joint = model_.joints[stop.joint];
    J(stop_row_[s], joint.v_index) = stop_sign_[s];
    row_links_[stop_row_[s]] = {stop.joint, 0};  // its joint moves link stop.joint: the chain holds the column
    const double coordinate = q[joint.q_index];
    const double gap = stop_sign_[s] > 0.0 ? coordinate - stop.lower : stop.upper - coordinate;
    offset_[stop_row_[s]] = gap_velocity(gap, stop_sign_[s] * v[joint.v_index], stop.restitution);
  }
  // A line's row measures the rate of its slack, length - |p_b - p_a|: with u the unit
  // vector from p_a to p_b, d(slack)/dt = u . v_a(p_a) - u . v_b(p_b). Its impulse z >= 0
  // pulls a towards b and b towards a (tension), and it enters, like a stop, when it is
  // taut within the margin or would be at the step's unconstrained velocity.
  row = rows_before_lines;
  for (size_t l = 0; l < contacts_.lines.size(); ++l) {
    const TensionLine& line = contacts_.lines[l];
    line_row_[l] = -1;
    line_point_a_[l] = data.X_world_link[line.link_a].act_point(line.point_a);
    line_point_b_[l] = data.X_world_link[line.link_b].act_point(line.point_b);
    const Vector3 span = line_point_b_[l] - line_point_a_[l];
    const double distance = span.norm();
    const double slack = line.length - distance;
    if (!(slack < line.length)) continue;  // both ends at one point: no direction, and far from taut
    line_direction_[l] = span / distance;
    J.row(row).setZero();
    add_point_row(row, line.link_a, line_point_a_[l], line_direction_[l], 1.0, data);
    add_point_row(row, line.link_b, line_point_b_[l], line_direction_[l], -1.0, data);
    const double free_rate = J.row(row).dot(free_velocity_);
    if (std::min(slack, slack + h * free_rate) >= contacts_.margin) continue;
    row_links_[row] = {line.link_a, line.link_b};
    offset_[row] = gap_velocity(slack, J.row(row).dot(v), line.restitution);
    line_row_[l] = row++;
  }
  rows = row;
  report.taut_lines = rows - rows_before_lines;
  report.rows = rows;
  return solve_and_advance(report, h, q, v);
}

ContactStepReport ContactStepper::solve_and_advance(ContactStepReport report, double h, VectorX& q, VectorX& v) {
  const int rows = report.rows, bilateral = report.constraint_rows;
  const auto J = jacobian_.topRows(rows);
  const auto mu = friction_coefficient_.head(rows);
  const auto normal_of = friction_normal_.head(rows);

  if (rows > 0) {
    // A = J M^-1 J^T, q_lcp = J v* + b.
    // Column by column (Eigen's blocked kernels would take packing buffers from the heap
    // beyond 128 kB, which a step must not do).
    auto minv_jt = minv_jacobian_t_.leftCols(rows);
    for (int r = 0; r < rows; ++r) {
      auto column = minv_jt.col(r);
      column = J.row(r).transpose();
      solve_tree(model_.velocity_coordinate_parent, mass_factor_, column);
    }
    // A's row i = sum over the columns c that row i of J touches of J(i, c) (M^-1 J^T)
    // row c: a contact row touches only the joints from its two links to the root (12
    // columns for two free bodies), so this is |row| times cheaper than the dense product.
    auto A = delassus_.topLeftCorner(rows, rows);
    A.setZero();
    for (int r = 0; r < rows; ++r)
      for_each_row_column(r, [&](int c) { A.row(r) += J(r, c) * minv_jt.row(c); });
    const double eps = options_.regularization * A.diagonal().mean();
    A.diagonal().array() += eps;
    auto lcp_offset = offset_.head(rows);
    lcp_offset.noalias() += J * free_velocity_;
    auto z = impulses_.head(rows);
    auto centre = previous_impulses_.head(rows);
    // eps I moves the answer by O(eps / smallest eigenvalue of A on its range) -- 4e-8 of
    // the weights in a 20-box stack. The proximal-point iteration (Rockafellar 1976)
    // removes that: z = SOL(A + eps I, b - eps z_centre) is a solution of the unregularized
    // problem once z = z_centre, and the error shrinks by about eps / (sigma + eps) per
    // solve. The centre is the last step's impulses when the rows are the same (a
    // resting contact: one solve, already converged); else 0, and a second solve from
    // the first answer.
    const bool same_rows = rows == previous_rows_;
    if (!same_rows) centre.setZero();
    z = centre;  // the warm start of projected Gauss-Seidel
    const ComplementarityProblem problem =
        bilateral > 0
            ? ComplementarityProblem{A, lcp_offset, lower_.head(rows), upper_.head(rows), normal_of, mu}
            : ComplementarityProblem{A, lcp_offset, std::nullopt, std::nullopt, normal_of, mu};
    for (int solve = 0; solve < (same_rows || eps == 0.0 ? 1 : 2); ++solve) {
      lcp_offset.noalias() -= eps * centre;
      report.solve = solve_complementarity(problem, workspace_, z, options_.solvers);
      if (!report.solve.solved() && problem.has_friction() && chain_has_dantzig_) {
        z = centre;
        report.solve = solve_with_fixed_friction_bounds(problem, z, report.solve);
      }
      if (!report.solve.solved()) return report;
      lcp_offset.noalias() += eps * centre;
      centre = z;
    }
    velocity_next_.noalias() = minv_jt * z;
    velocity_next_ += free_velocity_;
  } else {
    velocity_next_ = free_velocity_;
  }
  previous_rows_ = rows;
  integrate_configuration(model_, q, velocity_next_, h, configuration_next_);
  for (const int j : free_joints_) {
    const Joint& joint = model_.joints[j];
    const auto orientation = [&](const VectorX& coordinates) {
      return Eigen::Quaterniond(coordinates[joint.q_index + 3], coordinates[joint.q_index + 4],
                                coordinates[joint.q_index + 5], coordinates[joint.q_index + 6])
          .normalized();
    };
    const Eigen::Quaterniond before = orientation(q), after = orientation(configuration_next_);
    auto linear = velocity_next_.segment<3>(joint.v_index + 3);
    const Vector3 linear_parent = before * Vector3(linear);
    configuration_next_.segment<3>(joint.q_index) = q.segment<3>(joint.q_index) + h * linear_parent;
    linear = after.conjugate() * linear_parent;
  }
  q.swap(configuration_next_);
  v.swap(velocity_next_);
  return report;
}

// Friction boxes that move with the normal impulses take the pivoting solvers outside
// their theory, and Dantzig can cycle on them (a container's four corners sliding). Held
// fixed, the problem is a boxed MLCP with a positive definite A, which Dantzig solves;
// the boxes are then set from the normal impulses found and the solve repeated until
// the normal impulses stop changing -- the friction half of a staggered scheme (Kaufman,
// Sueda, James & Pai 2008). With redundant points (a box face's four corners) the split
// of the load among them is set only by the regularization, and the iteration settles
// it slowly, or not at all (two splits in turn: seen on a box pushed 1 % past its
// friction polygon). It stops at the first round whose answer holds the problem with
// moving boxes to a relative residual of 1e-8, when the normal impulses change by less
// than 1e-8 of the largest, or after 50 rounds, and takes the round with the smallest
// residual if that is at most 1e-6 (docs/physics/contact.md); else the chain's failure
// stands.
ComplementarityResult ContactStepper::solve_with_fixed_friction_bounds(const ComplementarityProblem& problem,
                                                                       VectorView z,
                                                                       const ComplementarityResult& chain) {
  const int rows = problem.size();
  auto lower = fixed_lower_.head(rows), upper = fixed_upper_.head(rows);
  auto best = best_impulses_.head(rows);
  const ComplementarityProblem boxed{problem.M, problem.q, lower, upper};
  ComplementarityResult result = chain, best_result = chain;
  best_result.residual = std::numeric_limits<double>::infinity();
  for (int round = 1; round <= 50; ++round) {
    double change = 0.0, scale = 0.0;
    for (int i = 0; i < rows; ++i) {
      if (problem.is_friction_row(i)) {
        upper[i] = problem.upper_bound(i, z);
        lower[i] = -upper[i];
      } else {
        lower[i] = problem.lower_bound(i, z);
        upper[i] = problem.upper_bound(i, z);
      }
    }
    for (int i = 0; i < rows; ++i)
      if (!problem.is_friction_row(i)) previous_normal_[i] = z[i];
    const ComplementarityResult solve = dantzig(boxed, workspace_.dantzig, z, options_.solvers.dantzig);
    if (!solve.solved()) break;
    for (int i = 0; i < rows; ++i)
      if (!problem.is_friction_row(i)) {
        change = std::max(change, std::abs(z[i] - previous_normal_[i]));
        scale = std::max(scale, std::abs(z[i]));
      }
    evaluate_residual(problem, z, workspace_.dantzig.direction_w.head(rows), result);
    result.solver = ComplementaritySolver::dantzig;
    result.pivots = solve.pivots;
    result.iterations = round;
    result.attempts = chain.attempts + 1;
    if (result.residual < best_result.residual) {
      best_result = result;
      best = z;
    }
    if (result.residual <= 1e-8 || change <= 1e-8 * scale) break;
  }
  if (!(best_result.residual <= 1e-6)) return chain;  // the chain's failure stands
  z = best;
  best_result.status = ComplementarityStatus::solved;
  best_result.message.clear();
  return best_result;
}

Vector3 ContactStepper::contact_impulse_world(int k) const {
  const ContactPoint& c = points_[k];
  const int row = contact_first_row_[k];
  Vector3 impulse = impulses_[row] * c.normal_world;
  for (int d = 0; d < friction_rows_[k]; ++d) impulse += impulses_[row + 1 + d] * friction_direction(c, d, friction_rows_[k]);
  return impulse;
}

double ContactStepper::contact_spin_impulse(int k) const {
  return spin_rows_[k] ? impulses_[contact_first_row_[k] + 1 + friction_rows_[k]] : 0.0;
}

double ContactStepper::stop_impulse(int s) const { return stop_row_[s] < 0 ? 0.0 : impulses_[stop_row_[s]]; }

}  // namespace heavesim
