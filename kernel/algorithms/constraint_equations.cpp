#include "kernel/algorithms/constraint_equations.hpp"

#include <array>
#include <cmath>
#include <numbers>

namespace heavesim {
namespace {

/// Everything a row needs about the two frames, in world coordinates.
struct FrameState {
  Vector3 p_a, p_b;       // frame origins [m]
  Matrix3 R_a, R_b;       // frame axes
  Motion v_a, v_b;        // spatial velocities of the two links (about the world origin)
  Vector3 pdot_a, pdot_b; // velocities of the frame origins [m/s]
};

FrameState frame_state(const Data& data, const Constraint& constraint) {
  const Transform A = constraint_frame_a(data, constraint), B = constraint_frame_b(data, constraint);
  FrameState state;
  state.p_a = A.translation();
  state.p_b = B.translation();
  state.R_a = A.rotation();
  state.R_b = B.rotation();
  state.v_a = data.velocity_world[constraint.link_a];
  state.v_b = data.velocity_world[constraint.link_b];
  state.pdot_a = state.v_a.point_velocity(state.p_a);
  state.pdot_b = state.v_b.point_velocity(state.p_b);
  return state;
}

/// The angle row theta = atan2(s, c), s = y_A . x_B, c = x_A . x_B (frames' world
/// axes). With e_s = x_B x y_A and e_c = x_B x x_A, s' = e_s . (w_b - w_a) and
/// c' = e_c . (w_b - w_a) (each axis turns with its link: x' = w x x), so
///   theta' = (c s' - s c') / (s^2 + c^2) = w . (w_b - w_a),  w = (c e_s - s e_c) / n,
/// n = s^2 + c^2 (docs/physics/drivers.md). n = 0 (x_B along z_A) leaves the angle
/// undefined: no direction then.
struct AngleTerms {
  double s = 0.0, c = 0.0, n = 0.0;
  Vector3 e_s, e_c;
};
AngleTerms angle_terms(const FrameState& f) {
  AngleTerms a;
  const Vector3 x_a = f.R_a.col(0), y_a = f.R_a.col(1), x_b = f.R_b.col(0);
  a.s = y_a.dot(x_b);
  a.c = x_a.dot(x_b);
  a.n = a.s * a.s + a.c * a.c;
  a.e_s = x_b.cross(y_a);
  a.e_c = x_b.cross(x_a);
  return a;
}
Vector3 angle_rate_axis(const FrameState& f) {
  const AngleTerms a = angle_terms(f);
  if (!(a.n > 0.0)) return Vector3::Zero();
  return (a.c * a.e_s - a.s * a.e_c) / a.n;
}
/// dw/dt for angle_rate_axis: the quotient rule on (c e_s - s e_c) / n with
/// e_s' = x_B' x y_A + x_B x y_A', e_c' likewise, and n' = 2 (s s' + c c').
Vector3 angle_rate_axis_rate(const FrameState& f) {
  const AngleTerms a = angle_terms(f);
  if (!(a.n > 0.0)) return Vector3::Zero();
  const Vector3 x_a = f.R_a.col(0), y_a = f.R_a.col(1), x_b = f.R_b.col(0);
  const Vector3 w_a = f.v_a.angular(), w_b = f.v_b.angular(), relative = w_b - w_a;
  const Vector3 x_a_dot = w_a.cross(x_a), y_a_dot = w_a.cross(y_a), x_b_dot = w_b.cross(x_b);
  const double s_dot = a.e_s.dot(relative), c_dot = a.e_c.dot(relative);
  const Vector3 e_s_dot = x_b_dot.cross(y_a) + x_b.cross(y_a_dot);
  const Vector3 e_c_dot = x_b_dot.cross(x_a) + x_b.cross(x_a_dot);
  const double n_dot = 2.0 * (a.s * s_dot + a.c * c_dot);
  const Vector3 numerator = a.c * a.e_s - a.s * a.e_c;
  const Vector3 numerator_dot = c_dot * a.e_s + a.c * e_s_dot - s_dot * a.e_c - a.s * e_c_dot;
  return (numerator_dot - numerator * (n_dot / a.n)) / a.n;
}

/// theta - f wrapped into (-pi, pi]: the angle driver's residual, continuous however
/// many turns theta and f have made.
double wrapped_angle(double angle) {
  double wrapped = std::remainder(angle, 2.0 * std::numbers::pi);  // [-pi, pi]
  if (wrapped <= -std::numbers::pi) wrapped += 2.0 * std::numbers::pi;
  return wrapped;
}

/// G_B: the world spatial force direction on link_b with phi' = G_B . (v_b - v_a).
Force row_direction(const ConstraintRow& row, const FrameState& f) {
  switch (row.kind) {
    case ConstraintRowKind::along: {
      const Vector3 d = f.R_a.col(row.axis_a);
      return Force(f.p_b.cross(d), d);
    }
    case ConstraintRowKind::perpendicular:
      return Force(-f.R_a.col(row.axis_a).cross(f.R_b.col(row.axis_b)), Vector3::Zero());
    case ConstraintRowKind::distance: {
      const Vector3 r = f.p_b - f.p_a;
      return Force(f.p_b.cross(r), r);
    }
    case ConstraintRowKind::length: {
      // d|r|/dt = u . (pdot_b - pdot_a), u = r / |r|; as for `distance`, the moment
      // p_b x u makes G_B . (v_b - v_a) read link a's velocity at p_b, which differs
      // from pdot_a by w_a x r, normal to u.
      const double length = (f.p_b - f.p_a).norm();
      if (!(length > 0.0)) return Force::Zero();  // coincident points: no direction
      const Vector3 u = (f.p_b - f.p_a) / length;
      return Force(f.p_b.cross(u), u);
    }
    case ConstraintRowKind::angle:
      return Force(angle_rate_axis(f), Vector3::Zero());
    case ConstraintRowKind::coupler:
    case ConstraintRowKind::driver:
    case ConstraintRowKind::expression:
    case ConstraintRowKind::stop:
      break;
  }
  return Force::Zero();
}

/// dG_B/dt.
Force row_direction_rate(const ConstraintRow& row, const FrameState& f) {
  switch (row.kind) {
    case ConstraintRowKind::along: {
      const Vector3 d = f.R_a.col(row.axis_a), d_dot = f.v_a.angular().cross(d);
      return Force(f.pdot_b.cross(d) + f.p_b.cross(d_dot), d_dot);
    }
    case ConstraintRowKind::perpendicular: {
      const Vector3 a = f.R_a.col(row.axis_a), b = f.R_b.col(row.axis_b);
      const Vector3 a_dot = f.v_a.angular().cross(a), b_dot = f.v_b.angular().cross(b);
      return Force(-(a_dot.cross(b) + a.cross(b_dot)), Vector3::Zero());
    }
    case ConstraintRowKind::distance: {
      const Vector3 r = f.p_b - f.p_a, r_dot = f.pdot_b - f.pdot_a;
      return Force(f.pdot_b.cross(r) + f.p_b.cross(r_dot), r_dot);
    }
    case ConstraintRowKind::length: {
      const Vector3 r = f.p_b - f.p_a, r_dot = f.pdot_b - f.pdot_a;
      const double length = r.norm();
      if (!(length > 0.0)) return Force::Zero();
      const Vector3 u = r / length, u_dot = (r_dot - u * u.dot(r_dot)) / length;
      return Force(f.pdot_b.cross(u) + f.p_b.cross(u_dot), u_dot);
    }
    case ConstraintRowKind::angle:
      return Force(angle_rate_axis_rate(f), Vector3::Zero());
    case ConstraintRowKind::coupler:
    case ConstraintRowKind::driver:
    case ConstraintRowKind::expression:
    case ConstraintRowKind::stop:
      break;
  }
  return Force::Zero();
}

/// The nearest link above (or at) both `a` and `b`, 0 for the ground: links are numbered
/// depth first, so a parent's index is below its children's and the larger index steps up.
int nearest_common_ancestor(const Model& model, int a, int b) {
  while (a != b) {
    if (a > b)
      a = model.joints[a].parent;
    else
      b = model.joints[b].parent;
  }
  return a;
}

/// Spatial acceleration of a link when qdd = 0: the sum of velocity-product terms c_i
/// along its path to the ground.
Motion acceleration_without_qdd(const Model& model, const Data& data, int link) {
  Motion a = Motion::Zero();
  for (int i = link; i > 0; i = model.joints[i].parent) a += data.bias_acceleration_world[i];
  return a;
}

/// An expression constraint's x_k = values[index[k]] (q) or its rates (v), gathered on
/// the stack: the builder allows at most max_variables of them.
using ExpressionPoint = std::array<double, ExpressionConstraint::max_variables>;
ExpressionPoint gather(const std::vector<int>& index, const VectorX& values) {
  ExpressionPoint x{};
  for (std::size_t k = 0; k < index.size(); ++k) x[k] = values[index[k]];
  return x;
}

/// df/dx at (data.q, t) into `gradient`; returns df/dt.
double expression_gradient(const ExpressionConstraint& expression, const Data& data, double t,
                           ExpressionPoint& gradient) {
  const ExpressionPoint x = gather(expression.q_index, data.q);
  double time_partial = 0.0;
  expression.function->gradient(x.data(), t, gradient.data(), time_partial);
  return time_partial;
}

}  // namespace

bool driver_is_angular(const Model& model, const Constraint& driver) {
  if (std::holds_alternative<AngleDriverConstraint>(driver.kind)) return true;
  const auto* joint_driver = std::get_if<DriverConstraint>(&driver.kind);
  if (!joint_driver) return false;
  const JointType& type = model.joints[joint_driver->joint].type;
  if (std::holds_alternative<PrismaticJoint>(type)) return false;
  if (std::holds_alternative<CylindricalJoint>(type)) return joint_driver->coordinate == 0;
  return true;
}

Transform constraint_frame_a(const Data& data, const Constraint& constraint) {
  return data.X_world_link[constraint.link_a] * constraint.X_linkA_frame;
}
Transform constraint_frame_b(const Data& data, const Constraint& constraint) {
  return data.X_world_link[constraint.link_b] * constraint.X_linkB_frame;
}

void constraint_residual(const Model& model, const Data& data, const VectorX& q, double t,
                         Eigen::Ref<VectorX> residual) {
  for (const Constraint& constraint : model.constraints) {
    if (const auto* driver = std::get_if<DriverConstraint>(&constraint.kind)) {
      residual[constraint.first_row] =
          q[model.joints[driver->joint].q_index + driver->coordinate] - driver->motion(t).position;
      continue;
    }
    if (const auto* stop = std::get_if<JointStopConstraint>(&constraint.kind)) {
      residual[constraint.first_row] = data.constraint_active[constraint.first_row] *
                                       stop->side * (q[model.joints[stop->joint].q_index] - stop->bound);
      continue;
    }
    if (const auto* expression = std::get_if<ExpressionConstraint>(&constraint.kind)) {
      residual[constraint.first_row] = expression->function->value(gather(expression->q_index, q).data(), t);
      continue;
    }
    if (const auto* coupler = std::get_if<CouplerConstraint>(&constraint.kind)) {
      residual[constraint.first_row] = q[model.joints[coupler->joint_a].q_index] -
                                       coupler->ratio * q[model.joints[coupler->joint_b].q_index] - coupler->offset;
      continue;
    }
    const auto* distance = std::get_if<DistanceConstraint>(&constraint.kind);  // `distance` rows have one
    const Transform A = constraint_frame_a(data, constraint), B = constraint_frame_b(data, constraint);
    const Vector3 r = B.translation() - A.translation();
    for (std::size_t k = 0; k < constraint.rows.size(); ++k) {
      const ConstraintRow& row = constraint.rows[k];
      double& value = residual[constraint.first_row + static_cast<int>(k)];
      switch (row.kind) {
        case ConstraintRowKind::along: value = A.rotation().col(row.axis_a).dot(r); break;
        case ConstraintRowKind::perpendicular:
          value = A.rotation().col(row.axis_a).dot(B.rotation().col(row.axis_b));
          break;
        case ConstraintRowKind::distance:
          value = 0.5 * (r.squaredNorm() - distance->distance * distance->distance);
          break;
        case ConstraintRowKind::length: value = r.norm(); break;
        case ConstraintRowKind::angle:
          value = std::atan2(A.rotation().col(1).dot(B.rotation().col(0)), A.rotation().col(0).dot(B.rotation().col(0)));
          break;
        case ConstraintRowKind::coupler:
        case ConstraintRowKind::driver:
        case ConstraintRowKind::expression:
        case ConstraintRowKind::stop: break;
      }
    }
    // A driver on frames: its one row is the measured coordinate minus f(t).
    if (const DriverFunction* motion = constraint.driver_motion()) {
      double& value = residual[constraint.first_row];
      value -= (*motion)(t).position;
      if (std::holds_alternative<AngleDriverConstraint>(constraint.kind)) value = wrapped_angle(value);
    }
  }
}

void constraint_jacobian(const Model& model, const Data& data, double t, Eigen::Ref<MatrixX> jacobian) {
  jacobian.setZero();
  for (const Constraint& constraint : model.constraints) {
    if (const auto* expression = std::get_if<ExpressionConstraint>(&constraint.kind)) {
      // Phi = f(x): J_row = df/dx on the rates of x (for scalar coordinates qdot_k = v_k).
      ExpressionPoint gradient;
      expression_gradient(*expression, data, t, gradient);
      for (std::size_t k = 0; k < expression->v_index.size(); ++k)
        jacobian(constraint.first_row, expression->v_index[k]) += gradient[k];
      continue;
    }
    if (const auto* driver = std::get_if<DriverConstraint>(&constraint.kind)) {
      jacobian(constraint.first_row, model.joints[driver->joint].v_index + driver->coordinate) = 1.0;
      continue;
    }
    if (const auto* stop = std::get_if<JointStopConstraint>(&constraint.kind)) {
      jacobian(constraint.first_row, model.joints[stop->joint].v_index) =
          data.constraint_active[constraint.first_row] * stop->side;
      continue;
    }
    if (const auto* coupler = std::get_if<CouplerConstraint>(&constraint.kind)) {
      jacobian(constraint.first_row, model.joints[coupler->joint_a].v_index) = 1.0;
      jacobian(constraint.first_row, model.joints[coupler->joint_b].v_index) = -coupler->ratio;
      continue;
    }
    const FrameState frames = frame_state(data, constraint);
    // J_row = G . (J_b - J_a): columns of the joints above b count +, above a count -. The
    // joints above both (from their nearest common ancestor up: a floating platform's six
    // columns under a loop on the rig) move the two frames alike and would be added and
    // taken away again, d - d = 0 exactly for a finite d: the paths stop there (the zeros
    // stand; a NaN or infinite d made NaN there before, and makes it elsewhere in the row now).
    const int common = nearest_common_ancestor(model, constraint.link_a, constraint.link_b);
    for (std::size_t k = 0; k < constraint.rows.size(); ++k) {
      const Force G = row_direction(constraint.rows[k], frames);
      auto row = jacobian.row(constraint.first_row + static_cast<int>(k));
      for (int i = constraint.link_b; i != common; i = model.joints[i].parent)
        for (int c = 0; c < model.joints[i].nv; ++c)
          row[model.joints[i].v_index + c] += dot(data.motion_subspace_world.col(model.joints[i].v_index + c), G);
      for (int i = constraint.link_a; i != common; i = model.joints[i].parent)
        for (int c = 0; c < model.joints[i].nv; ++c)
          row[model.joints[i].v_index + c] -= dot(data.motion_subspace_world.col(model.joints[i].v_index + c), G);
    }
  }
}

void constraint_velocity_target(const Model& model, const Data& data, double t, Eigen::Ref<VectorX> target) {
  target.setZero();
  for (const Constraint& constraint : model.constraints) {
    if (const DriverFunction* motion = constraint.driver_motion()) target[constraint.first_row] = (*motion)(t).velocity;
    // dPhi/dt = f_x . xdot + f_t = 0, so J v = -f_t.
    if (const auto* expression = std::get_if<ExpressionConstraint>(&constraint.kind)) {
      ExpressionPoint gradient;
      target[constraint.first_row] = -expression_gradient(*expression, data, t, gradient);
    }
  }
}

void constraint_bias(const Model& model, const Data& data, double t, Eigen::Ref<VectorX> bias) {
  for (const Constraint& constraint : model.constraints) {
    if (const auto* driver = std::get_if<DriverConstraint>(&constraint.kind)) {
      bias[constraint.first_row] = driver->motion(t).acceleration;
      continue;
    }
    if (std::holds_alternative<CouplerConstraint>(constraint.kind) || constraint.is_unilateral()) {
      bias[constraint.first_row] = 0.0;
      continue;
    }
    if (const auto* expression = std::get_if<ExpressionConstraint>(&constraint.kind)) {
      // d2Phi/dt2 = f_x . xdd + (v' f_xx v + 2 f_xt . v + f_tt): gamma is minus the second part.
      const ExpressionPoint x = gather(expression->q_index, data.q), rates = gather(expression->v_index, data.v);
      bias[constraint.first_row] = -expression->function->second_derivative_along(x.data(), rates.data(), t);
      continue;
    }
    const FrameState frames = frame_state(data, constraint);
    const Motion relative_velocity = frames.v_b - frames.v_a;
    const Motion relative_bias_acceleration = acceleration_without_qdd(model, data, constraint.link_b) -
                                              acceleration_without_qdd(model, data, constraint.link_a);
    for (std::size_t k = 0; k < constraint.rows.size(); ++k) {
      const ConstraintRow& row = constraint.rows[k];
      // phi'' = dG/dt . (v_b - v_a) + G . (a_b - a_a); the part without qdd is -gamma.
      bias[constraint.first_row + static_cast<int>(k)] =
          -(dot(relative_velocity, row_direction_rate(row, frames)) +
            dot(relative_bias_acceleration, row_direction(row, frames)));
    }
    // A driver on frames: Phi = g(q) - f(t), so gamma gains + f''(t).
    if (const DriverFunction* motion = constraint.driver_motion())
      bias[constraint.first_row] += (*motion)(t).acceleration;
  }
}

Force constraint_wrench(const Model&, const Data& data, const Constraint& constraint, const VectorX& lambda) {
  if (!constraint.acts_on_frames()) return Force::Zero();
  const FrameState frames = frame_state(data, constraint);
  Force wrench = Force::Zero();
  for (std::size_t k = 0; k < constraint.rows.size(); ++k)
    wrench += row_direction(constraint.rows[k], frames) * lambda[constraint.first_row + static_cast<int>(k)];
  return wrench;
}

void add_constraint_loads(const Model& model, const Data& data, double t, const VectorX& lambda,
                          AlignedVector<Force>& external_forces_world, VectorX& tau) {
  for (const Constraint& constraint : model.constraints) {
    if (const auto* expression = std::get_if<ExpressionConstraint>(&constraint.kind)) {
      ExpressionPoint gradient;
      expression_gradient(*expression, data, t, gradient);
      for (std::size_t k = 0; k < expression->v_index.size(); ++k)
        tau[expression->v_index[k]] += gradient[k] * lambda[constraint.first_row];
      continue;
    }
    if (const auto* driver = std::get_if<DriverConstraint>(&constraint.kind)) {
      tau[model.joints[driver->joint].v_index + driver->coordinate] += lambda[constraint.first_row];
      continue;
    }
    if (const auto* coupler = std::get_if<CouplerConstraint>(&constraint.kind)) {
      const double force = lambda[constraint.first_row];
      tau[model.joints[coupler->joint_a].v_index] += force;
      tau[model.joints[coupler->joint_b].v_index] -= coupler->ratio * force;
      continue;
    }
    if (const auto* stop = std::get_if<JointStopConstraint>(&constraint.kind)) {
      tau[model.joints[stop->joint].v_index] += data.constraint_active[constraint.first_row] * stop->side *
                                                lambda[constraint.first_row];
      continue;
    }
    const Force wrench = constraint_wrench(model, data, constraint, lambda);
    external_forces_world[constraint.link_b] += wrench;
    external_forces_world[constraint.link_a] -= wrench;
  }
}

}  // namespace heavesim
