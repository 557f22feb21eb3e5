#pragma once
// Pipeline stages (MuJoCo-style): positions, then velocities. Every dynamics
// algorithm reads what these stages leave in Data, so the work is done once per
// state and optional passes can be skipped.
#include "kernel/model/data.hpp"

namespace heavesim {

/// Position stage for configuration q (nq): link placements X_world_link, motion
/// subspaces S in world coordinates, world spatial inertias.
/// Quaternions in q need not be exactly unit: joints use q/|q|.
void update_positions(const Model& model, Data& data, const VectorX& q);

/// Velocity stage for joint velocities v (nv) at configuration q; requires update_positions(q).
/// Fills v_i = v_parent + S_i v_i, c_i = v_i x (S_i v_i) + X_world_link c_J,
/// the momenta h_i = I_i v_i and the gyroscopic bias forces v_i x* h_i.
void update_velocities(const Model& model, Data& data, const VectorX& q, const VectorX& v);

/// Momentum I_i v [N s, N m s] of link i moving with v: rigid plus any added inertia,
/// world coordinates about the world origin; requires update_positions.
inline Force link_momentum(const Model& model, const Data& data, int i, const Motion& v) {
  Force h = data.rigid_inertia_world[i] * v;
  if (model.links[i].added_inertia) h += data.added_inertia_world[i] * v;
  return h;
}

/// S_i x: the spatial motion of joint `joint` for its nv speeds or accelerations, read from
/// `values` (nv) at the joint's v_index, world coordinates; requires update_positions.
/// Fixed-size for one and six coordinates (a free joint's product would otherwise take
/// Eigen's dynamic-size path); one function for the velocity stage and RNEA.
inline Motion joint_motion(const Data& data, const Joint& joint, const VectorX& values) {
  switch (joint.nv) {
    case 0:
      return Motion::Zero();
    case 1:
      return Motion(data.motion_subspace_world.col(joint.v_index) * values[joint.v_index]);
    case 6:
      return Motion(data.motion_subspace_world.middleCols<6>(joint.v_index) * values.segment<6>(joint.v_index));
    default:
      return Motion(data.motion_subspace_world.middleCols(joint.v_index, joint.nv) *
                    values.segment(joint.v_index, joint.nv));
  }
}

/// The weight m g of link i at its centre of mass [N; N m about the world origin], world
/// axes; requires update_positions. Computed where a force balance needs it (RNEA, ABA),
/// not stored by the position stage: the mass matrix does not need it (CRBA from q on the
/// double pendulum 5 % faster without it, docs/performance.md).
inline Force link_weight(const Model& model, const Data& data, int i) {
  const Inertia& inertia = data.rigid_inertia_world[i];
  return Force::at_point(inertia.com(), inertia.mass() * model.gravity);
}

/// Total spatial inertia of link i as a 6x6 matrix (world coordinates about the origin).
inline Matrix6 link_inertia_matrix(const Model& model, const Data& data, int i) {
  Matrix6 I = data.rigid_inertia_world[i].matrix();
  if (model.links[i].added_inertia) I += data.added_inertia_world[i];
  return I;
}

}  // namespace heavesim
