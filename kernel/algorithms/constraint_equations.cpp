#include "kernel/algorithms/constraint_equations.hpp"

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
    case ConstraintRowKind::coupler:
    case ConstraintRowKind::driver:
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
    case ConstraintRowKind::coupler:
    case ConstraintRowKind::driver:
      break;
  }
  return Force::Zero();
}

/// Spatial acceleration of a link when qdd = 0: the sum of velocity-product terms c_i
/// along its path to the ground.
Motion acceleration_without_qdd(const Model& model, const Data& data, int link) {
  Motion a = Motion::Zero();
  for (int i = link; i > 0; i = model.joints[i].parent) a += data.bias_acceleration_world[i];
  return a;
}

}  // namespace

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
    if (const auto* coupler = std::get_if<CouplerConstraint>(&constraint.kind)) {
      residual[constraint.first_row] = q[model.joints[coupler->joint_a].q_index] -
                                       coupler->ratio * q[model.joints[coupler->joint_b].q_index] - coupler->offset;
      continue;
    }
    const auto* distance = std::get_if<DistanceConstraint>(&constraint.kind);  // distance rows have one
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
        case ConstraintRowKind::coupler:
        case ConstraintRowKind::driver: break;
      }
    }
  }
}

void constraint_jacobian(const Model& model, const Data& data, Eigen::Ref<MatrixX> jacobian) {
  jacobian.setZero();
  for (const Constraint& constraint : model.constraints) {
    if (const auto* driver = std::get_if<DriverConstraint>(&constraint.kind)) {
      jacobian(constraint.first_row, model.joints[driver->joint].v_index + driver->coordinate) = 1.0;
      continue;
    }
    if (const auto* coupler = std::get_if<CouplerConstraint>(&constraint.kind)) {
      jacobian(constraint.first_row, model.joints[coupler->joint_a].v_index) = 1.0;
      jacobian(constraint.first_row, model.joints[coupler->joint_b].v_index) = -coupler->ratio;
      continue;
    }
    const FrameState frames = frame_state(data, constraint);
    for (std::size_t k = 0; k < constraint.rows.size(); ++k) {
      const Force G = row_direction(constraint.rows[k], frames);
      auto row = jacobian.row(constraint.first_row + static_cast<int>(k));
      // J_row = G . (J_b - J_a): columns of the joints above b count +, above a count -
      // (common ancestors cancel).
      for (int i = constraint.link_b; i > 0; i = model.joints[i].parent)
        for (int c = 0; c < model.joints[i].nv; ++c)
          row[model.joints[i].v_index + c] += dot(data.motion_subspace_world.col(model.joints[i].v_index + c), G);
      for (int i = constraint.link_a; i > 0; i = model.joints[i].parent)
        for (int c = 0; c < model.joints[i].nv; ++c)
          row[model.joints[i].v_index + c] -= dot(data.motion_subspace_world.col(model.joints[i].v_index + c), G);
    }
  }
}

void constraint_velocity_target(const Model& model, double t, Eigen::Ref<VectorX> target) {
  target.setZero();
  for (const Constraint& constraint : model.constraints)
    if (const auto* driver = std::get_if<DriverConstraint>(&constraint.kind))
      target[constraint.first_row] = driver->motion(t).velocity;
}

void constraint_bias(const Model& model, const Data& data, double t, Eigen::Ref<VectorX> bias) {
  for (const Constraint& constraint : model.constraints) {
    if (const auto* driver = std::get_if<DriverConstraint>(&constraint.kind)) {
      bias[constraint.first_row] = driver->motion(t).acceleration;
      continue;
    }
    if (std::holds_alternative<CouplerConstraint>(constraint.kind)) {
      bias[constraint.first_row] = 0.0;
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

void add_constraint_loads(const Model& model, const Data& data, const VectorX& lambda,
                          AlignedVector<Force>& external_forces_world, VectorX& tau) {
  for (const Constraint& constraint : model.constraints) {
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
    const Force wrench = constraint_wrench(model, data, constraint, lambda);
    external_forces_world[constraint.link_b] += wrench;
    external_forces_world[constraint.link_a] -= wrench;
  }
}

}  // namespace heavesim
